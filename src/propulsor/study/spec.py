"""A study file (TOML): the base part file, the parameters to vary, the objectives, the requirements
and the depth of each evaluation; read and checked whole before anything runs (InputError, exit 2).

    [study]
    part = "../parts/final_drive.toml"   # the base part file, relative to the study file
    depth = "design"                      # design | proof | build
    title = "Final drive: face width x module"
    # sample = 20, seed = 1               # a random sample of the space instead of the whole grid

    [vary]
    module_mm = [8.0, 9.0, 10.0]                          # values
    width_planet_mm = { from = 60.0, to = 80.0, step = 10.0 }   # a range with a step (both ends in)

    [objectives]
    minimize = ["ring_outer_d_mm"]
    maximize = ["strength_sun_planet_S_H"]
    require = ["all_checks_passed", "strength_sun_planet_S_H >= 1.0"]
    record = ["ratio_i_1H"]               # more derived values in the table
"""

from __future__ import annotations

import dataclasses
import hashlib
import itertools
import json
import math
import random
import re
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from ..errors import InputError, did_you_mean

DEPTHS = ("design", "proof", "build")
#: most variants a study may name (a grid grows fast: refused before anything runs)
MAX_VARIANTS = 100_000
#: largest study file read
MAX_STUDY_BYTES = 1 << 20
#: the pseudo-value every evaluation has: no check of the evaluation failed unexpectedly
ALL_CHECKS = "all_checks_passed"
_OPS = {">=": lambda a, b: a >= b, "<=": lambda a, b: a <= b, ">": lambda a, b: a > b, "<": lambda a, b: a < b,
        "==": lambda a, b: a == b, "!=": lambda a, b: a != b}
_REQ = re.compile(r"^\s*([A-Za-z_][A-Za-z0-9_.]*)\s*(>=|<=|==|!=|>|<)\s*([-+0-9.eE]+|true|false)\s*$")
_KEYS = {"study": {"part", "depth", "title", "sample", "seed"}, "vary": None,
         "objectives": {"minimize", "maximize", "require", "record"}}


@dataclass(frozen=True)
class Requirement:
    name: str
    op: str | None = None  # None: the value itself must be true (all_checks_passed)
    bound: Any = None

    def __str__(self) -> str:
        return self.name if self.op is None else f"{self.name} {self.op} {self.bound}"

    def holds(self, value) -> bool:
        if self.op is None:
            return value is True
        if value is None or (isinstance(value, float) and math.isnan(value)):
            return False
        try:
            return bool(_OPS[self.op](value, self.bound))
        except TypeError:
            return False


@dataclass(frozen=True)
class Study:
    path: Path
    title: str
    part_file: Path  # absolute
    part_type: str
    base: dict  # the part file's values (its mapping), as read
    depth: str
    varied: tuple[str, ...]
    variants: tuple[dict, ...]  # each: {parameter: value}, in the order of `varied`
    minimize: tuple[str, ...]
    maximize: tuple[str, ...]
    require: tuple[Requirement, ...]
    record: tuple[str, ...]

    @property
    def objectives(self) -> tuple[str, ...]:
        return self.minimize + self.maximize

    @property
    def values(self) -> tuple[str, ...]:
        """Every derived value the table gives (objectives, requirements, recorded), once each."""
        names = [*self.objectives, *(r.name for r in self.require), *self.record]
        return tuple(dict.fromkeys(n for n in names if n != ALL_CHECKS and n not in self.varied))


def variant_key(study: Study, values: dict, version: str) -> str:
    """The variant's identity for --resume: its parameters (base part and overrides), the depth and the
    project version."""
    text = json.dumps({"type": study.part_type, "base": study.base, "values": values, "depth": study.depth,
                       "version": version}, sort_keys=True, default=str)
    return hashlib.sha256(text.encode()).hexdigest()[:16]


def _fields(part_type: str) -> dict:
    from typing import get_type_hints

    from ..parts import params_class

    cls = params_class(part_type)
    hints = get_type_hints(cls)
    return {f.name: (f, hints.get(f.name)) for f in dataclasses.fields(cls)}


def _check_value(name: str, value, field_and_type) -> None:
    """One value of a varied parameter against the field's type and limits (as a part file's)."""
    from ..params import _check_number, _check_type

    f, typ = field_and_type
    meta = f.metadata
    if typ in (bool, int, float, str, list):
        _check_type(name, value, typ)
    if meta.get("choices") is not None and value not in meta["choices"]:
        raise InputError(name, value, "must be one of " + ", ".join(map(str, meta["choices"])))
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        _check_number(name, value, meta, meta.get("unit", ""), integer=typ is int)


def _values_of(name: str, spec, fld, sampling: bool) -> list | tuple:
    """The values of one varied parameter: a list, or a range {from, to, step} (a sampler needs no
    step: it draws within the range)."""
    where = f"vary.{name}"
    if isinstance(spec, list):
        if not spec:
            raise InputError(where, spec, "must name at least one value")
        for v in spec:
            _check_value(name, v, fld)
        # each value once, in order (a list parameter's values are lists: told apart by their text)
        return list({json.dumps(v, sort_keys=True): v for v in spec}.values())
    if not isinstance(spec, dict):
        raise InputError(where, spec, "must be a list of values or a range { from = A, to = B, step = S }")
    unknown = set(spec) - {"from", "to", "step"}
    if unknown:
        raise InputError(f"{where}.{sorted(unknown)[0]}", spec[sorted(unknown)[0]], "unknown key (from, to, step)")
    if "from" not in spec or "to" not in spec or ("step" not in spec and not sampling):
        raise InputError(where, spec, "a range needs from, to and step (step only without a sampler)")
    lo, hi = spec["from"], spec["to"]
    for v in (lo, hi):
        _check_value(name, v, fld)
    if not hi >= lo:
        raise InputError(where, spec, "to must be >= from")
    integer = fld[1] is int
    if sampling:
        return (lo, hi, integer)
    from ..numbers import number

    step = number(spec["step"], f"{where}.step")
    if not step > 0:
        raise InputError(f"{where}.step", step, "must be a number > 0")
    if integer and not isinstance(step, int):
        raise InputError(f"{where}.step", step, "must be a whole number (the parameter is whole)")
    if (hi - lo) / step > MAX_VARIANTS:  # before counting: a step of 5e-324 names more values than a float holds
        raise InputError(where, spec, f"names more than {MAX_VARIANTS} values")
    n = int(math.floor((hi - lo) / step + 1e-9)) + 1
    if n > MAX_VARIANTS:
        raise InputError(where, spec, f"names more than {MAX_VARIANTS} values")
    vals = [lo + k * step for k in range(n)]
    # decimal steps without binary drift (0.1 + 0.2): as many decimals as the numbers written
    if not integer:
        digits = max(_decimals(x) for x in (lo, hi, step))
        vals = [round(float(v), digits) for v in vals]
    return vals


def _decimals(x) -> int:
    text = repr(float(x))
    return len(text.split(".")[1]) if "." in text and "e" not in text else 12


def _names(section: dict, key: str) -> tuple[str, ...]:
    v = section.get(key, [])
    if not isinstance(v, list) or not all(isinstance(x, str) for x in v):
        raise InputError(f"objectives.{key}", v, "must be a list of names (strings)")
    return tuple(v)


def _requirement(text) -> Requirement:
    if not isinstance(text, str):
        raise InputError("objectives.require", text, 'must be strings: "all_checks_passed" or "NAME >= NUMBER"')
    if text.strip() == ALL_CHECKS:
        return Requirement(ALL_CHECKS)
    m = _REQ.match(text)
    if not m:
        raise InputError("objectives.require", text, 'must be "all_checks_passed" or "NAME OP NUMBER" '
                         "(OP one of >=, <=, >, <, ==, !=)")
    raw = m.group(3)
    bound = raw == "true" if raw in ("true", "false") else float(raw)
    if isinstance(bound, float) and not math.isfinite(bound):
        raise InputError("objectives.require", text, "the bound must be a finite number")
    return Requirement(m.group(1), m.group(2), bound)


def _glossary_names(part_type: str) -> list[str]:
    """The derived values the part type's glossary names exactly (not its patterns)."""
    from ..export.glossary import Glossary
    from ..parts import glossary_of

    return list(Glossary(glossary_of(part_type)).exact)


def is_manifest_value(part_type: str, name: str) -> bool:
    """`name` is a derived value the part type's manifest can give (its glossary, or the common one)."""
    from ..export.glossary import Glossary
    from ..parts import glossary_of

    return Glossary(glossary_of(part_type)).lookup(name) is not None


def _base_design_names(part_type: str, base: dict, part_file: Path) -> set[str]:
    """The names of the derived values the base part's design gives (those the glossary leaves to the
    build's own descriptions); the base part's InputError as it is."""
    from ..params import load_params
    from ..parts import get_part_type
    from .evaluate import Variant, design_values

    pt = get_part_type(part_type)
    part = Variant(pt, load_params(pt.params_cls, dict(base), type_name=pt.name), part_file)
    derived, _ = design_values(part)
    return set(derived)


def load_study(path: str | Path) -> Study:
    """The study file at `path`, checked whole (InputError naming the first bad key)."""
    import tomllib

    from ..params import read_part_file
    from ..regular_file import read_regular

    path = Path(path)
    try:
        raw = read_regular(path, MAX_STUDY_BYTES)
    except InputError:
        raise
    except ValueError as exc:
        raise InputError("STUDY", str(path), str(exc)) from None
    except OSError as exc:
        raise InputError("STUDY", str(path), f"cannot be read ({exc.strerror or exc})") from None
    from ..numbers import nesting
    from ..params import toml_error

    try:
        doc = tomllib.loads(raw.decode("utf-8"))
    except UnicodeDecodeError as exc:
        raise InputError("STUDY", str(path), f"is not UTF-8 ({exc.reason} at byte {exc.start})") from None
    except ValueError as exc:  # TOMLDecodeError, or an integer of more than 4 300 digits
        raise InputError("STUDY", str(path), toml_error(exc)) from None
    except RecursionError:
        raise InputError("STUDY", str(path), "nests arrays or tables too deeply") from None
    nesting(doc, "STUDY", 4)
    for key, value in doc.items():
        if key not in _KEYS:
            raise InputError(key, value, "unknown section of a study file (study, vary, objectives)")
        if not isinstance(value, dict):
            raise InputError(key, value, "must be a table")
        allowed = _KEYS[key]
        for k in value:
            if allowed is not None and k not in allowed:
                raise InputError(f"{key}.{k}", value[k], f"unknown key (known: {', '.join(sorted(allowed))})")
    st, vary, obj = doc.get("study", {}), doc.get("vary", {}), doc.get("objectives", {})
    part = st.get("part")
    if not isinstance(part, str) or not part:
        raise InputError("study.part", part, "must name the base part file (a path relative to the study file)")
    part_file = (path.parent / part).resolve()
    type_name, base = read_part_file(part_file)
    depth = st.get("depth", "design")
    if depth not in DEPTHS:
        raise InputError("study.depth", depth, f"must be one of {', '.join(DEPTHS)}")
    title = st.get("title", path.stem)
    if not isinstance(title, str):
        raise InputError("study.title", title, "must be a string")
    sample, seed = st.get("sample"), st.get("seed", 0)
    if sample is not None and (isinstance(sample, bool) or not isinstance(sample, int) or not 1 <= sample <= MAX_VARIANTS):
        raise InputError("study.sample", sample, f"must be a whole number of variants within 1 ... {MAX_VARIANTS}")
    if isinstance(seed, bool) or not isinstance(seed, int):
        raise InputError("study.seed", seed, "must be a whole number")

    fields = _fields(type_name)
    if not vary:
        raise InputError("vary", vary, "must name at least one parameter to vary")
    values = {}
    for name, spec in vary.items():
        if name not in fields or name == "type":
            raise InputError(f"vary.{name}", spec, f"unknown parameter of {type_name} (see `propulsor params {type_name}`)",
                             did_you_mean(name, [f for f in fields if f != "type"]))
        values[name] = _values_of(name, spec, fields[name], sample is not None)
    varied = tuple(values)
    if sample is None:
        count = math.prod(len(v) for v in values.values())
        if count > MAX_VARIANTS:
            raise InputError("vary", f"{count} variants", f"a grid of at most {MAX_VARIANTS} variants (or a sampler)")
        variants = tuple(dict(zip(varied, combo)) for combo in itertools.product(*values.values()))
    else:
        rng = random.Random(seed)
        seen, out = set(), []
        for _ in range(sample):
            v = {}
            for name, vals in values.items():
                if isinstance(vals, list):
                    v[name] = rng.choice(vals)
                else:
                    lo, hi, integer = vals
                    v[name] = rng.randint(lo, hi) if integer else rng.uniform(lo, hi)
            key = json.dumps(v, sort_keys=True)
            if key not in seen:
                seen.add(key)
                out.append(v)
        variants = tuple(out)

    minimize, maximize, record = _names(obj, "minimize"), _names(obj, "maximize"), _names(obj, "record")
    require = tuple(_requirement(t) for t in obj.get("require", []) or []) if isinstance(obj.get("require", []), list) \
        else (_requirement(obj.get("require")),)
    base_values = None  # the base part's own derived values at design depth, computed only when needed
    for where, names in (("minimize", minimize), ("maximize", maximize), ("record", record),
                         ("require", tuple(r.name for r in require))):
        for n in names:
            if n == ALL_CHECKS and where == "require":
                continue
            if is_manifest_value(type_name, n):
                continue
            if base_values is None:
                base_values = _base_design_names(type_name, base, part_file)
            if n not in base_values:
                raise InputError(f"objectives.{where}", n, f"is not a derived value of a {type_name} manifest",
                                 did_you_mean(n, sorted(set(_glossary_names(type_name)) | set(base_values))))
    if depth == "design":  # every name must be one the design gives (the base part's, as each variant's)
        if base_values is None:
            base_values = _base_design_names(type_name, base, part_file)
        for where, names in (("minimize", minimize), ("maximize", maximize), ("record", record),
                             ("require", tuple(r.name for r in require))):
            for n in names:
                if n != ALL_CHECKS and n not in base_values:
                    raise InputError(f"objectives.{where}", n, f"is not computed at depth design for this {type_name} "
                                     f"(its design gives {len(base_values)} values); depth proof or build may give it")
    if not minimize and not maximize:
        raise InputError("objectives", obj, "must name at least one value to minimize or maximize")
    return Study(path, title, part_file, type_name, base, depth, varied, variants, minimize, maximize, require, record)
