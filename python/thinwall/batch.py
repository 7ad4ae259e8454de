"""Many parts on a Dask cluster: one task per part, one row per part and per
feature, written to Parquet (``parts.parquet``, ``features.parquet``). A
part that fails is a row that says why (the exception's kind, code and
message), never the end of the batch.

The same call runs on a laptop (a ``LocalCluster`` of one worker process per
core) and on a cluster (``scheduler="tcp://host:8786"`` or a ``client``);
every worker needs the ``thinwall`` package and the parts' paths. The
command line's ``thinwall batch`` keeps its local run (threads, one report
file per part).

Needs ``pip install "dask[distributed]" pyarrow``.
"""
from __future__ import annotations

import os
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Callable, Dict, Iterable, List, Optional, Tuple

import thinwall

PART_COLUMNS = (
    "file", "ok", "faces", "stiffness_features", "machining_features", "seconds",
    "error_kind", "error_code", "error_status", "error_message",
)
FEATURE_COLUMNS = (
    "file", "family", "id", "kind", "body", "thin", "thickness_mm", "height_mm", "length_mm",
    "depth_mm", "width_mm", "step_ids", "occ_indices",
)


@dataclass
class BatchResult:
    """Where the rows went, and how many parts failed."""

    parts_path: Path
    features_path: Path
    parts: int
    failed: int


def _feature_row(file: str, family: str, f: "thinwall.Feature") -> Dict[str, Any]:
    d = f.to_dict()
    return {
        "file": file,
        "family": family,
        "id": d.get("id"),
        "kind": d.get("kind"),
        "body": d.get("body"),
        "thin": d.get("thin"),
        "thickness_mm": d.get("thickness"),
        "height_mm": d.get("height"),
        "length_mm": d.get("length"),
        "depth_mm": d.get("depth"),
        "width_mm": d.get("width"),
        "step_ids": [x.step_id for x in f.faces],
        "occ_indices": [x.occ_index for x in f.faces],
    }


def recognize_rows(path: str, options: Dict[str, Any]) -> Tuple[Dict[str, Any], List[Dict[str, Any]]]:
    """One part's row and its features' rows (a Dask task)."""
    t0 = time.perf_counter()
    row: Dict[str, Any] = dict.fromkeys(PART_COLUMNS)
    row.update(file=path, ok=False, faces=0, stiffness_features=0, machining_features=0)
    features: List[Dict[str, Any]] = []
    try:
        r = thinwall.recognize(path, **options)
        features = [_feature_row(path, "stiffness", f) for f in r.stiffness_features]
        features += [_feature_row(path, "machining", f) for f in r.machining_features]
        row.update(
            ok=True,
            faces=r.to_dict()["part"]["faces"],
            stiffness_features=len(r.stiffness_features),
            machining_features=len(r.machining_features),
        )
    except thinwall.ThinwallError as e:
        row.update(error_kind=e.kind, error_code=e.code, error_status=e.status_name, error_message=str(e))
    except Exception as e:  # a defect of the package, kept as the part's row
        row.update(error_kind="internal", error_code="python", error_message=f"{type(e).__name__}: {e}")
    row["seconds"] = time.perf_counter() - t0
    return row, features


def _client(scheduler: Optional[str], client: Any, workers: Optional[int]):
    """The client to use and whether this call owns it (and its cluster)."""
    from distributed import Client, LocalCluster

    if client is not None:
        return client, False
    if scheduler is not None:
        return Client(scheduler), True
    n = workers or os.cpu_count() or 1
    cluster = LocalCluster(n_workers=n, threads_per_worker=1, processes=True, dashboard_address=None)
    return Client(cluster), True


def _write(rows: List[Dict[str, Any]], columns: Tuple[str, ...], types: Dict[str, Any], path: Path) -> None:
    import pyarrow as pa
    import pyarrow.parquet as pq

    schema = pa.schema([(c, types[c]) for c in columns])
    table = pa.Table.from_pylist([{c: r.get(c) for c in columns} for r in rows], schema=schema)
    pq.write_table(table, path)


def _types():
    import pyarrow as pa

    text, real, whole = pa.string(), pa.float64(), pa.int64()
    parts = dict.fromkeys(PART_COLUMNS, text)
    parts.update(ok=pa.bool_(), faces=whole, stiffness_features=whole, machining_features=whole, seconds=real)
    features = dict.fromkeys(FEATURE_COLUMNS, text)
    features.update(body=whole, thin=pa.bool_(), step_ids=pa.list_(whole), occ_indices=pa.list_(whole))
    for c in ("thickness_mm", "height_mm", "length_mm", "depth_mm", "width_mm"):
        features[c] = real
    return parts, features


def batch(
    parts: Iterable[Any],
    out: Any,
    *,
    scheduler: Optional[str] = None,
    client: Any = None,
    workers: Optional[int] = None,
    progress: Optional[Callable[[int, int, Dict[str, Any]], None]] = None,
    **options: Any,
) -> BatchResult:
    """Recognize every part (paths) on a Dask cluster with ``options`` (as
    :func:`thinwall.recognize`); write ``parts.parquet`` and
    ``features.parquet`` in ``out``, rows in the order of ``parts``.
    ``progress(done, total, part_row)`` is called as each part finishes."""
    from distributed import as_completed

    paths = [os.fspath(p) for p in parts]
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    c, owned = _client(scheduler, client, workers)
    try:
        futures = c.map(recognize_rows, paths, options=options, pure=False)
        order = {f.key: i for i, f in enumerate(futures)}
        done: List[Any] = [None] * len(paths)
        for k, future in enumerate(as_completed(futures), 1):
            done[order[future.key]] = future.result()
            if progress is not None:
                progress(k, len(paths), done[order[future.key]][0])
    finally:
        if owned:
            cluster = getattr(c, "cluster", None)
            c.close()
            if cluster is not None:
                cluster.close()
    part_rows = [r for r, _ in done]
    feature_rows = [f for _, fs in done for f in fs]
    part_types, feature_types = _types()
    result = BatchResult(out / "parts.parquet", out / "features.parquet", len(part_rows),
                         sum(1 for r in part_rows if not r["ok"]))
    _write(part_rows, PART_COLUMNS, part_types, result.parts_path)
    _write(feature_rows, FEATURE_COLUMNS, feature_types, result.features_path)
    return result
