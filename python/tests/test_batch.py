"""`thinwall.batch` on a two-worker Dask `LocalCluster` over 200 shared
parts and a corrupt file: the Parquet rows have the features `thinwall
batch` reports, and the corrupt file is a failed row."""
from __future__ import annotations

import json

import pytest

from conftest import SHARED, run_cli

pq = pytest.importorskip("pyarrow.parquet")
distributed = pytest.importorskip("distributed")
from thinwall.batch import batch  # noqa: E402

PARTS = SHARED[:200]


def test_a_dask_batch_has_the_cli_batchs_features_and_fails_one_row(tmp_path):
    assert len(PARTS) == 200, "the shared parts are there"
    corrupt = tmp_path / "corrupt.step"
    corrupt.write_bytes(b"ISO-10303-21;\nHEADER;\nENDSEC;\nDATA;\n#1=BROKEN(;\n")
    inputs = [str(p) for p in PARTS] + [str(corrupt)]
    seen = []
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster, distributed.Client(cluster) as c:
        result = batch(inputs, tmp_path / "dask", client=c,
                       progress=lambda k, n, row: seen.append((k, n)))
    assert (result.parts, result.failed) == (201, 1)
    assert seen[-1] == (201, 201)
    parts = pq.read_table(result.parts_path).to_pylist()
    features = pq.read_table(result.features_path).to_pylist()
    assert [r["file"] for r in parts] == inputs
    bad = parts[-1]
    assert (bad["ok"], bad["error_kind"], bad["error_code"]) == (False, "input", "read.syntax")
    assert bad["error_status"] == "TW_ERR_PARSE" and bad["error_message"]

    cli = run_cli("batch", "--out", str(tmp_path / "cli"), *inputs)
    assert cli.returncode == 1, cli.stderr  # the corrupt file
    summary = [json.loads(line) for line in (tmp_path / "cli" / "summary.jsonl").read_text().splitlines()]
    by_file = {s["file"]: s for s in summary}
    assert not by_file[str(corrupt)]["ok"]
    for row in parts[:-1]:
        line = by_file[row["file"]]
        assert row["ok"] == line["ok"], row["file"]
        report = json.loads((tmp_path / "cli" / line["report"]).read_text())
        expected = [("stiffness", f["id"], f["kind"], f["faces"]) for f in report["stiffness_features"]]
        expected += [("machining", f["id"], f["kind"], f["faces"]) for f in report["machining_features"]]
        got = [(f["family"], f["id"], f["kind"], f["step_ids"]) for f in features if f["file"] == row["file"]]
        assert got == expected, row["file"]
        assert row["faces"] == line["faces"]
    assert all(all(i is not None for i in f["occ_indices"]) for f in features)
