"""The Python results are the command line's JSON, and bad input raises the
documented exception with the command line's kind and exit code, the use
case's code and the C ABI's status."""
from __future__ import annotations

import ctypes
import json
from pathlib import Path

import pytest

import thinwall
from conftest import FIXTURES, ROOT, SHARED, run_cli


def rel(p: Path) -> str:
    return str(p.relative_to(ROOT))


@pytest.fixture(autouse=True)
def _at_root(monkeypatch):
    # Results name the part by the path given: the same relative path as
    # the command line's.
    monkeypatch.chdir(ROOT)


@pytest.mark.parametrize("path", FIXTURES, ids=lambda p: rel(p))
def test_recognize_equals_the_cli_on_every_fixture(path):
    cli = run_cli("recognize", rel(path))
    assert cli.returncode == 0, cli.stderr
    assert thinwall.recognize(rel(path)).to_dict() == json.loads(cli.stdout)


PANEL = "fixtures/recognition/rib_grid_panel.step"
COMMANDS = [
    ("plan", {"up": (0, 0, 1)}, ["--up", "0,0,1"]),
    ("plan", {}, []),
    ("access", {"up": (0, 0, 1), "tool_diameter": 10}, ["--up", "0,0,1", "--tool-diameter", "10"]),
    ("operations", {"up": (0, 0, 1)}, ["--up", "0,0,1", "--format", "json"]),
    ("operations", {"up": [(0, 0, 1), (0, 0, -1)]}, ["--up", "0,0,1", "--up", "0,0,-1", "--format", "json"]),
    ("inspect", {}, ["--format", "json"]),
    ("recognize", {"up": (0, 0, -1), "no_reach": True, "exclude": ["hole", "fillet"]},
     ["--up", "0,0,-1", "--no-reach", "--exclude", "hole,fillet"]),
]


@pytest.mark.parametrize("command,options,flags", COMMANDS, ids=lambda x: str(x)[:40])
def test_other_commands_equal_the_cli(command, options, flags):
    cli = run_cli(command, PANEL, *flags)
    assert cli.returncode == 0, cli.stderr
    assert getattr(thinwall, command)(PANEL, **options).to_dict() == json.loads(cli.stdout)


def test_classify_and_size_wall_equal_the_cli():
    d = "fixtures/classify/blind_slot"
    cli = run_cli("classify", "--part", f"{d}/part.step", "--volume", f"{d}/v0.step", "--up", "0,0,1")
    assert cli.returncode == 0, cli.stderr
    py = thinwall.classify(f"{d}/part.step", [f"{d}/v0.step"], up=(0, 0, 1))
    assert py.to_dict() == json.loads(cli.stdout)
    assert len(py) == 1
    cli = run_cli("size-wall", "--length", "100", "--thickness", "2", "--height", "30")
    assert thinwall.size_wall(length=100, thickness=2, height=30).to_dict() == json.loads(cli.stdout)


def test_a_part_read_once_or_from_bytes_gives_the_same_results():
    by_path = thinwall.recognize(PANEL, up=(0, 0, 1)).to_dict()
    part = thinwall.read(PANEL)
    assert part.face_count == by_path["part"]["faces"]
    assert thinwall.recognize(part, up=(0, 0, 1)).to_dict() == by_path
    from_bytes = thinwall.recognize(Path(PANEL).read_bytes(), up=(0, 0, 1)).to_dict()
    assert from_bytes["part"]["file"] == "<bytes>"
    from_bytes["part"]["file"] = PANEL
    assert from_bytes == by_path


def test_typed_results_name_features_and_their_faces():
    r = thinwall.recognize(PANEL, up=(0, 0, 1))
    kinds = [f.kind for f in r.stiffness_features]
    assert kinds.count("web") == 1 and kinds.count("rib") == 3
    assert len(list(r)) == len(r) == len(r.stiffness_features) + len(r.machining_features)
    table = {(f["body"], f["step_id"]): f["occ_index"] for f in r.to_dict()["faces"]}
    for feature in r:
        assert feature.faces, feature
        for face in feature.faces:
            assert face.occ_index == table[(face.body, face.step_id)]
    assert "W1" in str(r) and "web" in repr(r)
    assert [f.face.step_id for f in thinwall.access(PANEL, up=(0, 0, 1))] == [
        f["step_id"] for f in r.to_dict()["faces"]
    ]


def c_status(data: bytes) -> int:
    """The C ABI's status for reading `data` (libthinwall.so)."""
    lib = ctypes.CDLL(str(ROOT / "target" / "release" / "libthinwall.so"))
    out = ctypes.c_void_p()
    status = lib.tw_part_load_memory(data, ctypes.c_size_t(len(data)), ctypes.byref(out))
    if out:
        lib.tw_part_free(out)
    return status


NIST_TESSELLATED = [p for p in SHARED if "ftc_08" in p.name]
BAD_FILES = [
    ("garbage", b"this is not STEP", "read.syntax"),
    ("truncated", Path(ROOT / PANEL).read_bytes()[:5000], "read.syntax"),
] + [("tessellated", p.read_bytes(), "read.no_brep") for p in NIST_TESSELLATED]


@pytest.mark.parametrize("name,data,code", BAD_FILES, ids=[b[0] for b in BAD_FILES])
def test_bad_input_raises_the_cli_kind_and_the_c_status(tmp_path, name, data, code):
    path = tmp_path / f"{name}.step"
    path.write_bytes(data)
    cli = run_cli("recognize", str(path))
    with pytest.raises(thinwall.InputError) as raised:
        thinwall.recognize(str(path))
    e = raised.value
    assert (e.kind, e.code) == ("input", code)
    assert e.exit_code == cli.returncode == 1
    assert e.status == c_status(data) and e.status_name.startswith("TW_ERR_")
    with pytest.raises(thinwall.InputError) as from_bytes:
        thinwall.read(data)
    assert from_bytes.value.code == code


def test_bad_values_raise_usage_errors_with_the_cli_exit_code():
    cases = [
        ({"up": (0, 0, 0)}, "setup.zero_up", ["--up", "0,0,0"]),
        ({"tool_diameter": -1}, "recognition.config.preferred_tool_diameter", ["--tool-diameter", "-1"]),
        ({"bogus": 3}, "usage", ["--bogus", "3"]),
        ({"machine": "7-axis"}, "usage", ["--machine", "7-axis"]),
    ]
    for options, code, flags in cases:
        cli = run_cli("recognize", PANEL, *flags)
        with pytest.raises(thinwall.UsageError) as raised:
            thinwall.recognize(PANEL, **options)
        e = raised.value
        assert e.kind == "usage" and e.exit_code == cli.returncode == 2, (options, cli.stderr)
        assert e.code.split(".")[0] == code.split(".")[0], (options, e.code)
        assert isinstance(e, thinwall.ThinwallError)
    with pytest.raises(TypeError):
        thinwall.recognize(PANEL, format="text")
    with pytest.raises(thinwall.InputError) as missing:
        thinwall.recognize("no/such/part.step")
    assert missing.value.code == "read.io" and missing.value.status_name == "TW_ERR_IO"


def test_work_runs_with_the_gil_released():
    """Another Python thread runs while a part is recognized: with the GIL
    held through the call it would stand still for the whole call."""
    import threading
    import time

    large = next(p for p in SHARED if "ftc_07" in p.name)
    part = thinwall.read(str(large))
    done = threading.Event()
    took = []

    def work():
        t0 = time.perf_counter()
        thinwall._native.run(["recognize", str(large)], part)
        took.append(time.perf_counter() - t0)
        done.set()

    t = threading.Thread(target=work)
    longest, last = 0.0, time.perf_counter()
    t.start()
    while not done.is_set():
        now = time.perf_counter()
        longest, last = max(longest, now - last), now
    t.join()
    assert took[0] > 0.1, "the call is long enough to tell"
    assert longest < 0.25 * took[0], (longest, took[0])
