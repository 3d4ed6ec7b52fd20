"""The backends the sweeps run their tasks on: a thread pool, a Dask client,
or serially (rollerrig.analysis.sweep's sweep and sweep_rig; the exact
table's build through sweep).  A task's failure names the task, Ctrl-C
cancels what has not started, and the progress bar is rollerrig's one
(rollerrig._progress)."""
from __future__ import annotations

import numbers
import os
import uuid
from concurrent.futures import FIRST_COMPLETED, Future, ThreadPoolExecutor, wait
from functools import partial
from typing import Any, Callable, Dict, Iterator, List, Mapping, Optional, Sequence, Tuple

from .. import _progress
from .._errors import RollerRigError
from .._optional import require


def check_options(func: str, backend: str, workers: Optional[int], client: Any,
                  progress: Optional[bool]) -> Tuple[str, int, Any]:
    """The backend actually used ("serial", "threads" or "dask"), the worker
    count and the Dask client (None but for "dask")."""
    if backend not in ("threads", "serial", "dask"):
        raise RollerRigError(f"{func}: backend must be 'threads', 'serial' or 'dask', "
                             f"got {backend!r}")
    if client is not None:
        if backend == "serial":
            raise RollerRigError(f"{func}: a Dask client was given with backend='serial'")
        backend = "dask"
    elif backend == "dask":
        distributed = require("distributed", f"{func}(backend='dask')", "distributed",
                              package="dask.distributed")
        try:
            client = distributed.get_client()
        except ValueError:
            raise RollerRigError(f"{func}: backend='dask' needs a dask.distributed Client "
                                 f"(client=...), and none is running") from None
    if workers is not None:
        if backend != "threads":
            raise RollerRigError(f"{func}: workers is for backend='threads' (a Dask client has "
                                 f"its own workers), got workers={workers!r} with "
                                 f"backend={backend!r}")
        if isinstance(workers, bool) or not isinstance(workers, numbers.Integral) \
                or workers < 1:
            raise RollerRigError(f"{func}: workers must be an integer >= 1, got {workers!r}")
    _progress.check(func, progress)
    if backend == "threads":
        slots = int(workers) if workers is not None else (os.cpu_count() or 1)
    elif backend == "dask":
        slots = max(1, sum(client.nthreads().values()))
    else:
        slots = 1
    return backend, slots, client


def execute(label: str, task: Callable[..., Any], items: Sequence[Any], sizes: Sequence[int],
            describe: Callable[[int], str], store: Callable[[int, Any], None],
            common: Mapping[str, Any], *, backend: str, slots: int, client: Any,
            progress: Optional[bool], unit: str) -> None:
    """Run task(item, **common) for every item and store(k, result) in this
    thread as each finishes.  A failing task raises RollerRigError naming
    describe(k); Ctrl-C cancels what has not started and raises
    KeyboardInterrupt."""
    n = len(items)
    bar = _progress.bar(progress, int(sum(sizes)), label, unit)
    done = 0

    def fail(k: int, exc: Exception) -> RollerRigError:
        return RollerRigError(f"{label}: {describe(k)} failed: {type(exc).__name__}: {exc}")

    def interrupted(cancelled: int) -> KeyboardInterrupt:
        return KeyboardInterrupt(f"{label} interrupted: {done} of {n} tasks done, "
                                 f"{cancelled} cancelled")
    try:
        if backend == "serial":
            for k, item in enumerate(items):
                try:
                    res = task(item, **common)
                except Exception as exc:
                    raise fail(k, exc) from exc
                except KeyboardInterrupt:
                    raise interrupted(n - done - 1) from None
                store(k, res)
                done += 1
                bar.update(sizes[k])
        elif backend == "threads":
            pool = ThreadPoolExecutor(max_workers=min(slots, n),
                                      thread_name_prefix="rollerrig-sweep")
            futures: Dict[Future[Any], int] = {}
            try:
                futures = {pool.submit(task, item, **common): k for k, item in enumerate(items)}
                pending = set(futures)
                while pending:
                    finished, pending = wait(pending, return_when=FIRST_COMPLETED)
                    for fut in sorted(finished, key=futures.__getitem__):
                        k = futures[fut]
                        try:
                            res = fut.result()
                        except Exception as exc:
                            raise fail(k, exc) from exc
                        store(k, res)
                        done += 1
                        bar.update(sizes[k])
            except KeyboardInterrupt:
                cancelled = sum(f.cancel() for f in futures)
                raise interrupted(cancelled) from None
            finally:
                # pending chunks are dropped; running ones (C loops that
                # cannot be stopped from here) end before we return
                pool.shutdown(wait=True, cancel_futures=True)
        else:
            tag = f"rollerrig-{label.replace('(', '-').rstrip(')')}-{uuid.uuid4().hex[:8]}"
            dask_futures = client.map(partial(task, **common), items,
                                      key=[f"{tag}-{k}" for k in range(n)], pure=False)
            index = {f.key: k for k, f in enumerate(dask_futures)}
            try:
                for dask_fut in _completed(client, dask_futures):
                    k = index[dask_fut.key]
                    try:
                        res = dask_fut.result()
                    except Exception as exc:
                        raise fail(k, exc) from exc
                    store(k, res)
                    dask_fut.release()
                    done += 1
                    bar.update(sizes[k])
            except KeyboardInterrupt:
                client.cancel(dask_futures)
                raise interrupted(n - done) from None
            except BaseException:
                client.cancel(dask_futures)
                raise
    finally:
        bar.close()


def _completed(client: Any, futures: List[Any]) -> Iterator[Any]:
    """dask's as_completed on `client`, which need not be the default client."""
    from distributed import as_completed
    # distributed leaves as_completed unannotated: its use here, typed
    completed: Callable[[List[Any]], Iterator[Any]] = as_completed
    with client.as_current():
        yield from completed(futures)
