"""An existing Dask cluster at ``--scheduler``: the address checked, the scheduler asked who it is within a
bounded time (connection, handshake and answer), and its workers waited for within a stated time.

Only ``tcp://HOST:PORT`` (or ``HOST:PORT``) is taken: ``tls://`` needs certificates and ``ws://``/``ucx://``
need packages and settings propulsor does not pass, so those are refused with one line (exit 2) instead of
failing inside Dask.  A listener that accepts and never answers, or answers with anything but a Dask
scheduler's identity, is "no Dask scheduler answers there" (exit 2) after :data:`ANSWER_TIMEOUT_S`.  A
scheduler with no worker is waited for :data:`WORKER_WAIT_S` (``--worker-wait``), then the environment
code (exit 3) with one line naming the address; the same when every worker has gone for that long in the
middle of a study (the finished rows stay in results.csv)."""

from __future__ import annotations

import errno
import re
import threading

from ..errors import EnvironmentFailure, InputError

#: seconds for the whole of connecting to a scheduler: TCP connection, Dask's handshake and its answer
ANSWER_TIMEOUT_S = 10.0
#: seconds a study waits for a first worker on a scheduler that has none (``--worker-wait``)
WORKER_WAIT_S = 60.0
#: the longest --worker-wait (a day)
WORKER_WAIT_MAX_S = 86_400.0

_HOST = r"(?:[A-Za-z0-9](?:[A-Za-z0-9-]{0,61}[A-Za-z0-9])?(?:\.[A-Za-z0-9](?:[A-Za-z0-9-]{0,61}[A-Za-z0-9])?)*|\[[0-9A-Fa-f:.]+\])"
_ADDRESS = re.compile(rf"^(?:tcp://)?({_HOST}):([0-9]{{1,5}})$")


def scheduler_address(text) -> str:
    """`text` as ``tcp://HOST:PORT``; InputError('--scheduler', …) for anything else."""
    if not isinstance(text, str) or not text.strip():
        raise InputError("--scheduler", text, "must be the address of a Dask scheduler, tcp://HOST:PORT")
    scheme = text.split("://", 1)[0].lower() if "://" in text else "tcp"
    if scheme != "tcp":
        raise InputError("--scheduler", text, f"{scheme}:// is not supported: give tcp://HOST:PORT (tls, ws and "
                         "ucx need certificates or packages propulsor does not set up)")
    m = _ADDRESS.match(text) if len(text) <= 300 and text.isascii() else None
    if m is None or not 1 <= int(m.group(2)) <= 65535:
        raise InputError("--scheduler", text, "must be tcp://HOST:PORT (a host name or IP address and a port "
                         "1 ... 65535)")
    return f"tcp://{m.group(1)}:{int(m.group(2))}"


def worker_wait(value) -> float:
    """The --worker-wait seconds: a finite number within 0 ... a day (InputError)."""
    import math

    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value) \
            or not 0 <= value <= WORKER_WAIT_MAX_S:
        raise InputError("--worker-wait", value, f"must be seconds within 0 ... {WORKER_WAIT_MAX_S:.0f}")
    return float(value)


def _ask_identity(address: str, timeout: float) -> dict:
    import asyncio

    from distributed.comm import connect

    async def ask():
        comm = await connect(address, timeout=timeout)
        try:
            await comm.write({"op": "identity", "reply": True})
            return await comm.read()
        finally:
            comm.abort()

    async def bounded():
        return await asyncio.wait_for(ask(), timeout)

    return asyncio.run(bounded())


def probe(address: str, timeout: float | None = None) -> dict:
    """The identity of the Dask scheduler at `address`, asked in a thread of its own within `timeout` s
    (:data:`ANSWER_TIMEOUT_S` when None) for all of it; InputError('--scheduler', …) when nothing answers, or
    the answer is not a scheduler's."""
    timeout = ANSWER_TIMEOUT_S if timeout is None else timeout
    box: dict = {}

    def ask():
        try:
            box["reply"] = _ask_identity(address, timeout)
        except BaseException as exc:  # noqa: BLE001 - whatever the comm raised: no scheduler answers
            box["error"] = exc

    t = threading.Thread(target=ask, name="propulsor-scheduler-probe", daemon=True)
    t.start()
    t.join(timeout + 2.0)
    reply = box.get("reply")
    if t.is_alive() or "error" in box or not (isinstance(reply, dict) and reply.get("type") == "Scheduler"):
        why = (f"nothing answered within {timeout:.0f} s" if t.is_alive() or isinstance(box.get("error"), TimeoutError)
               else f"{type(box['error']).__name__}" if "error" in box else "the answer is not a Dask scheduler's")
        raise InputError("--scheduler", address, f"no Dask scheduler answers there ({why}); start one with "
                         "`dask scheduler` and workers with `dask worker ADDRESS`")
    return reply


def no_worker(address: str, waited: float, during: bool = False) -> EnvironmentFailure:
    what = "every worker left the scheduler" if during else "the scheduler has no worker"
    return EnvironmentFailure(address, errno.ETIMEDOUT, "cannot run the study on", f"{what} and none joined within "
                              f"{waited:g} s (--worker-wait S waits longer; start workers with `dask worker "
                              f"{address}`)")


def wait_for_workers(client, address: str, wait: float, progress=lambda msg: None) -> int:
    """The scheduler's number of workers, once there is one; EnvironmentFailure after `wait` s without."""
    n = len(client.nthreads())
    if n:
        return n
    progress(f"{address}: no Dask worker yet; waiting up to {wait:g} s for one")
    try:
        client.wait_for_workers(1, timeout=wait)
    except (TimeoutError, OSError):
        raise no_worker(address, wait) from None
    return len(client.nthreads())
