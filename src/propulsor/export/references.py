"""The sources a report cites, with their full citations.

The code and its texts name a source by a short key: ``seed 004`` for one of the five source papers
(the numbering of the project's source collection), a standard by its designation (``ISO 6336-3``,
``GOST 19274-73``), a book by its authors.  :func:`cite` numbers the sources in the order a report
first names them: ``seed 004 eq. 13`` reads ``[2] eq. 13``, ``ISO 6336-3`` reads ``ISO 6336-3 [3]``,
and the report ends with a References section listing exactly those sources in full.
Russian titles are transliterated (BGN/PCGN) and translated in brackets.
"""

from __future__ import annotations

import re

#: (key, pattern of its mention in a text, what replaces the mention ({n}: its number), full citation)
SOURCES: tuple[tuple[str, str, str, str], ...] = (
    ("seed 000", r"\b[Ss]eed 000\b", "[{n}]",
     "Skoybeda A. T., Zhukovets V. N. *Obosnovaniye ratsional'noy skhemy silovogo privoda kolesno-shagayushchey "
     "khodovoy sistemy* [Substantiation of a rational power-drive scheme for a wheel-walking running system]. "
     "Belarusian National Technical University, Minsk; manuscript received 11 April 2023. In Russian."),
    ("seed 001", r"\b[Ss]eed 001\b", "[{n}]",
     "Skoybeda A. T., Zhukovets V. N. *Kolesno-shagayushchiye dvizhiteli dlya transportnogo sredstva vysokoy "
     "prokhodimosti* [Wheel-walking propulsors for a high-mobility vehicle]. *Teoreticheskaya i prikladnaya "
     "mekhanika* [Theoretical and Applied Mechanics], international scientific and technical collection, "
     "vol. 28, Minsk, 2013, pp. 228–233. In Russian."),
    ("seed 002", r"\b[Ss]eed 002\b", "[{n}]",
     "Belarusian National Technical University, Minsk: construction of the involute tooth profiles of the "
     "noncircular gears in the drive of the wheel-walking propulsor, with the sector tables of the driving "
     "gear and the driven gear's spaces (Tables 2–4); the copy used has no title block, the title is "
     "descriptive. Continues Skoybeda A. T., Zhukovets V. N. *Raschet nachal'nykh liniy nekruglykh "
     "zubchatykh koles* [Calculation of the pitch curves of noncircular gears], *Teoreticheskaya i "
     "prikladnaya mekhanika*, vol. 31, 2016, pp. 110–117. In Russian."),
    ("seed 003", r"\b[Ss]eed 003\b", "[{n}]",
     "Skoybeda A. T., Dan'kov A. M. *Nauchnyye osnovy sozdaniya reguliruyemykh peredach s sostavnymi "
     "zubchatymi kolesami* [Scientific foundations of adjustable transmissions with composite gears]. "
     "Belarusian National Technical University, Minsk; Mogilev State Technical University, Mogilev. "
     "UDC 621.833.01. In Russian."),
    ("seed 004", r"\b[Ss]eed 004\b", "[{n}]",
     "Taratorkin A. I. *Razrabotka gusenichnogo konteynerovoza polnoy massoy 50 tonn* [Development of a "
     "tracked container carrier of 50 t gross mass]. Master's thesis, explanatory note; supervisor "
     "E. B. Sarach. Bauman Moscow State Technical University, faculty of Special Machine Building, "
     "department SM9 Multipurpose Tracked Vehicles and Mobile Robots, Moscow, 2021. In Russian."),
    ("ISO 21771", r"\bISO 21771(?::2007)?\b", "{m} [{n}]",
     "ISO 21771:2007. *Gears — Cylindrical involute gears and gear pairs — Concepts and geometry.* "
     "International Organization for Standardization, Geneva."),
    ("ISO 6336-1", r"\bISO 6336-1(?::2019)?\b", "{m} [{n}]",
     "ISO 6336-1:2019. *Calculation of load capacity of spur and helical gears — Part 1: Basic principles, "
     "introduction and general influence factors.* ISO, Geneva."),
    ("ISO 6336-2", r"\bISO 6336-2(?::2019)?\b", "{m} [{n}]",
     "ISO 6336-2:2019. *Calculation of load capacity of spur and helical gears — Part 2: Calculation of "
     "surface durability (pitting).* ISO, Geneva."),
    ("ISO 6336-3", r"\bISO 6336-3(?::2019)?\b", "{m} [{n}]",
     "ISO 6336-3:2019. *Calculation of load capacity of spur and helical gears — Part 3: Calculation of "
     "tooth bending strength.* ISO, Geneva."),
    ("ISO 6336-5", r"\bISO 6336-5(?::2016)?\b", "{m} [{n}]",
     "ISO 6336-5:2016. *Calculation of load capacity of spur and helical gears — Part 5: Strength and "
     "quality of materials.* ISO, Geneva."),
    ("ISO 6336", r"\bISO 6336\b(?!-)", "{m} [{n}]",
     "ISO 6336 (all parts). *Calculation of load capacity of spur and helical gears.* ISO, Geneva."),
    ("ISO 53", r"\bISO 53(?::1998)?\b", "{m} [{n}]",
     "ISO 53:1998. *Cylindrical gears for general and heavy engineering — Standard basic rack tooth "
     "profile.* ISO, Geneva."),
    ("ISO 1328", r"\bISO 1328(?:-1)?(?::2013)?\b", "{m} [{n}]",
     "ISO 1328-1:2013. *Cylindrical gears — ISO system of flank tolerance classification — Part 1: "
     "Definitions and allowable values of deviations relevant to flanks of gear teeth.* ISO, Geneva."),
    ("ISO 76", r"\bISO 76(?::2006)?\b", "{m} [{n}]",
     "ISO 76:2006. *Rolling bearings — Static load ratings.* ISO, Geneva."),
    ("ISO 4156", r"\bISO 4156(?:-1)?\b", "{m} [{n}]",
     "ISO 4156-1:2005. *Straight cylindrical involute splines — Metric module, side fit — Part 1: "
     "Generalities.* ISO, Geneva."),
    ("GOST 16532-70", r"\bGOST 16532(?:-70)?\b", "{m} [{n}]",
     "GOST 16532-70. *Peredachi zubchatyye tsilindricheskiye evol'ventnyye vneshnego zatsepleniya. Raschet "
     "geometrii* [Cylindrical involute gear pairs of external mesh. Calculation of geometry]. Moscow."),
    ("GOST 19274-73", r"\bGOST 19274(?:-73)?\b", "{m} [{n}]",
     "GOST 19274-73. *Peredachi zubchatyye tsilindricheskiye evol'ventnyye vnutrennego zatsepleniya. Raschet "
     "geometrii* [Cylindrical involute gear pairs of internal mesh. Calculation of geometry]. Moscow."),
    ("GOST 13755-81", r"\bGOST 13755(?:-81)?\b", "{m} [{n}]",
     "GOST 13755-81. *Peredachi zubchatyye tsilindricheskiye evol'ventnyye. Iskhodnyy kontur* [Cylindrical "
     "involute gears. Basic rack]. Moscow."),
    ("GOST 9323-79", r"\bGOST 9323(?:-79)?\b", "{m} [{n}]",
     "GOST 9323-79. *Dolbyaki zuboreznyye chistovyye. Tekhnicheskiye usloviya* [Finishing gear shaper cutters. "
     "Specifications]. Moscow."),
    ("GOST 6033-80", r"\bGOST 6033(?:-80)?\b", "{m} [{n}]",
     "GOST 6033-80. *Soyedineniya shlitsevyye evol'ventnyye s uglom profilya 30°. Razmery, dopuski i "
     "izmeryayemyye velichiny* [Involute splined joints with a 30° pressure angle. Dimensions, tolerances "
     "and measured quantities]. Moscow."),
    ("GOST 21425-75", r"\bGOST 21425(?:-75)?\b", "{m} [{n}]",
     "GOST 21425-75. *Soyedineniya zubchatyye (shlitsevyye) pryamobochnyye. Metody rascheta nagruzochnoy "
     "sposobnosti* [Splined joints. Methods of calculating the load capacity]. Moscow."),
    ("GOST 23360-78", r"\bGOST 23360(?:-78)?\b", "{m} [{n}]",
     "GOST 23360-78. *Soyedineniya shponochnyye s prizmaticheskimi shponkami. Razmery shponok i secheniy "
     "pazov. Dopuski i posadki* [Parallel key joints. Dimensions of keys and keyways, tolerances and "
     "fits]. Moscow."),
    ("GOST 5721-75", r"\bGOST 5721(?:-75)?\b", "{m} [{n}]",
     "GOST 5721-75. *Podshipniki rolikovyye radial'nyye sfericheskiye dvukhryadnyye* [Double-row radial "
     "spherical roller bearings]. Moscow."),
    ("GOST 8338-75", r"\bGOST 8338(?:-75)?\b", "{m} [{n}]",
     "GOST 8338-75. *Podshipniki sharikovyye radial'nyye odnoryadnyye* [Single-row radial ball bearings]. "
     "Moscow."),
    ("GOST 8328-75", r"\bGOST 8328(?:-75)?\b", "{m} [{n}]",
     "GOST 8328-75. *Podshipniki rolikovyye radial'nyye s korotkimi tsilindricheskimi rolikami* [Radial "
     "roller bearings with short cylindrical rollers]. Moscow."),
    ("Litvin", r"\bLitvin (?:&|and) Fuentes(?:-Aznar)?(?: \(?2009\)?)?", "{m} [{n}]",
     "Litvin F. L., Fuentes-Aznar A., Gonzalez-Perez I., Hayasaka K. *Noncircular Gears: Design and "
     "Generation.* Cambridge University Press, Cambridge, 2009."),
    ("Pilkey", r"\bPeterson(?:'s)?(?: / Pilkey)?\b|\bPilkey\b", "{m} [{n}]",
     "Pilkey W. D., Pilkey D. F. *Peterson's Stress Concentration Factors*, 3rd ed. Wiley, Hoboken, 2008."),
    ("Timoshenko", r"\bTimoshenko (?:&|and) Goodier\b", "{m} [{n}]",
     "Timoshenko S. P., Goodier J. N. *Theory of Elasticity*, 3rd ed. McGraw-Hill, New York, 1970."),
)

_COMPILED = [(key, re.compile(rx), repl, full) for key, rx, repl, full in SOURCES]
CITATIONS = {key: full for key, _, _, full in SOURCES}


class Citer:
    """Numbers sources in the order of their first mention across every text it is given."""

    def __init__(self):
        self.numbers: dict[str, int] = {}

    def __call__(self, text) -> str:
        text = str(text)
        hits = []
        for key, rx, repl, _ in _COMPILED:
            for m in rx.finditer(text):
                if not any(m.start() < e and s < m.end() for s, e, *_ in hits):
                    hits.append((m.start(), m.end(), key, repl, m.group()))
        out, last = [], 0
        for start, end, key, repl, mention in sorted(hits):
            n = self.numbers.setdefault(key, len(self.numbers) + 1)
            out += [text[last:start], repl.format(n=n, m=mention)]
            last = end
        return "".join(out) + text[last:]

    def references(self) -> list[str]:
        """The References section's lines: ``[n] full citation``, by number."""
        return [f"\\[{n}\\] {CITATIONS[key]}" for key, n in sorted(self.numbers.items(), key=lambda kv: kv[1])]
