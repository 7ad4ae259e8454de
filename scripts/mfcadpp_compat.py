"""Run the MFCAD++ generator (written for pythonocc-core) on OCP.

The generator (MIT, `josephkwok986/mfcad2`, see ../shared/data/mfcadpp_gen/README.md) imports
`OCC.Core.<module>` and pythonocc's helpers. pythonocc-core is not on PyPI; OCP (cadquery-ocp)
wraps the same OpenCascade classes with other spellings. `install(upstream_dir)` makes the
generator's own files run unchanged on OCP:

- `OCC.Core.X` is a module that gives OCP.X's names plus pythonocc's spellings of static
  functions: `topods.Face`, `topods_Face`, `brepgprop_SurfaceProperties`, `gp_OZ`,
  `Interface_Static_SetCVal` (the class's static method `M_s`, or the function `M` where OCCT 8
  made the class a namespace, as `TopoDS`), and OCCT's collection typedefs
  (`TopTools_ListOfShape`, ...) that OCP 8 names by their templates.
- `OCC.Extend.TopologyUtils` is the generator's own `OCCUtils.Topology` (pythonocc's
  `TopologyExplorer` is that module's `Topo` under another name); `OCC.Extend.DataExchange`
  gives the STEP writer; `OCC.Display` is an empty stand-in (the generator imports it, never
  uses it without a screen).
- `BRep_Tool.Curve(edge)` returns (curve, first, last) as in pythonocc.
- Shapes compare the way pythonocc compares them: equal when `IsEqual` (same TShape, location
  and orientation); OCP compares by object identity. The hash is OCP's (pythonocc's rule:
  orientation ignored), so equal shapes hash alike.
- The generator's modules are read through a loader that changes only what pythonocc did
  differently: `except RuntimeError` also catches every OpenCascade failure OCP raises
  (`Standard_Failure`, `StdFail_NotDone`, ...: pythonocc raised each as RuntimeError), and
  numpy 2's `-np.inf` for the removed `np.NINF`.

No line of the generator is copied here; its logic, random draws and labels are its own.
"""

import importlib.abc
import importlib.machinery
import re
import sys
import types

import OCP  # noqa: F401  (fails early, with its own message, where OCP is missing)

_OCC_PACKAGES = ("OCC", "OCC.Core", "OCC.Extend", "OCC.Display")


def _static_spellings(module):
    """pythonocc's names for the static functions of each class in an OCP module."""
    extra = {}
    for cls_name in dir(module):
        cls = getattr(module, cls_name)
        namespace = isinstance(cls, types.ModuleType)
        if not (isinstance(cls, type) or namespace):
            continue
        methods = {}
        for attr in dir(cls):
            if attr.startswith("_"):
                continue
            name = attr[:-2] if attr.endswith("_s") else attr
            if attr.endswith("_s") or namespace:
                methods[name] = getattr(cls, attr)
                if not namespace and not hasattr(cls, name):
                    setattr(cls, name, methods[name])  # pythonocc: `BRep_Tool().Curve(e)`
        if not methods:
            continue
        space = types.SimpleNamespace(**methods)
        extra.setdefault(cls_name.lower(), space)
        for name, fn in methods.items():
            extra.setdefault(f"{cls_name}_{name}", fn)
            extra.setdefault(f"{cls_name.lower()}_{name}", fn)
    return extra


# OCCT's collection typedefs, which OCP 8 keeps in `OCP.OCP.collections` under template names.
_COLLECTIONS = {
    "TopTools_ListOfShape": "List_TopoDS_Shape",
    "TopTools_SequenceOfShape": "Sequence_TopoDS_Shape",
    "TopTools_IndexedMapOfShape": "IndexedMap_TopoDS_Shape_TopTools_ShapeMapHasher",
    "TopTools_IndexedDataMapOfShapeListOfShape":
        "IndexedDataMap_TopoDS_Shape_List_TopoDS_Shape_TopTools_ShapeMapHasher",
    "TColgp_Array1OfPnt": "Array1_gp_Pnt",
    "TColgp_Array1OfPnt2d": "Array1_gp_Pnt2d",
    "TColgp_Array1OfVec": "Array1_gp_Vec",
    "TColgp_HArray1OfPnt": "HArray1_gp_Pnt",
    "TColgp_SequenceOfVec": "Sequence_gp_Vec",
    "TColStd_HArray1OfBoolean": "HArray1_bool",
}


class TopTools_ListIteratorOfListOfShape:
    """OCCT's list iterator (More/Value/Next) over an OCP list, which Python iterates."""

    def __init__(self, shapes):
        self.items = list(shapes)
        self.at = 0

    def More(self):
        return self.at < len(self.items)

    def Value(self):
        return self.items[self.at]

    def Next(self):
        self.at += 1


def _occ_core_module(name):
    short = name.rsplit(".", 1)[1].lstrip("_")  # pythonocc's SWIG modules `_X` are `X`
    ocp = importlib.import_module("OCP." + short)
    mod = types.ModuleType(name)
    for attr in dir(ocp):
        if not attr.startswith("__"):
            setattr(mod, attr, getattr(ocp, attr))
    for attr, value in _static_spellings(ocp).items():
        if not hasattr(mod, attr):
            setattr(mod, attr, value)
    collections = importlib.import_module("OCP.OCP.collections")
    for typedef, template in _COLLECTIONS.items():
        if typedef.startswith(short + "_") and hasattr(collections, template):
            setattr(mod, typedef, getattr(collections, template))
    if short == "TopTools":
        mod.TopTools_ListIteratorOfListOfShape = TopTools_ListIteratorOfListOfShape
    mod.__getattr__ = lambda attr: _missing(f"{name}.{attr}")
    return mod


def _missing(what):
    """A name OCP does not wrap: importing it works, using it says what is missing."""

    def use(*args, **kwargs):
        raise NotImplementedError(f"{what} is not wrapped by OCP")

    if what.rsplit(".", 1)[1].startswith("__"):
        raise AttributeError(what)
    return use


def _topology_utils(name):
    topo = importlib.import_module("OCCUtils.Topology")
    from OCP.TopAbs import TopAbs_EDGE, TopAbs_FACE

    mod = types.ModuleType(name)
    mod.TopologyExplorer = topo.Topo
    mod.WireExplorer = topo.WireExplorer
    mod.is_edge = lambda s: s.ShapeType() == TopAbs_EDGE
    mod.is_face = lambda s: s.ShapeType() == TopAbs_FACE
    return mod


def _data_exchange(name):
    from OCP.STEPControl import STEPControl_Writer

    mod = types.ModuleType(name)
    mod.STEPControl_Writer = STEPControl_Writer
    return mod


def _package(name):
    mod = types.ModuleType(name)
    mod.__path__ = []
    return mod


class _OccFinder(importlib.abc.MetaPathFinder, importlib.abc.Loader):
    """Answers `import OCC...` with OCP-backed modules."""

    def find_spec(self, fullname, path=None, target=None):
        if fullname == "OCC" or fullname.startswith("OCC."):
            return importlib.machinery.ModuleSpec(
                fullname, self, is_package=fullname in _OCC_PACKAGES
            )
        return None

    def create_module(self, spec):
        name = spec.name
        if name in _OCC_PACKAGES:
            return _package(name)
        if name.startswith("OCC.Core."):
            return _occ_core_module(name)
        if name == "OCC.Extend.TopologyUtils":
            return _topology_utils(name)
        if name == "OCC.Extend.DataExchange":
            return _data_exchange(name)
        if name.startswith("OCC.Display."):
            mod = types.ModuleType(name)
            mod.__getattr__ = lambda attr: _missing(f"{name}.{attr}")
            return mod
        raise ImportError(f"no OCP stand-in for {name}")

    def exec_module(self, module):
        pass


def occt_failures():
    """Every exception class OCP raises for an OpenCascade failure (OCP gives each its own
    class, `StdFail_NotDone` is no `Standard_Failure`), once per process."""
    global _FAILURES
    if _FAILURES is None:
        core = importlib.import_module("OCP.OCP")
        found = set()
        for name in dir(core):
            mod = getattr(core, name)
            if isinstance(mod, types.ModuleType):
                found.update(c for c in vars(mod).values()
                             if isinstance(c, type) and issubclass(c, BaseException))
        _FAILURES = tuple(sorted(found, key=lambda c: c.__name__))
    return _FAILURES


_FAILURES = None
_FAILURE = "*__import__('mfcadpp_compat').occt_failures()"

# What pythonocc did differently, as (pattern, replacement); see the module's doc.
REWRITES = (
    (re.compile(r"except RuntimeError(?=\s*(:|as\b))"), f"except (RuntimeError, {_FAILURE})"),
    (re.compile(r"\bnp\.NINF\b"), "(-np.inf)"),
)


class _UpstreamLoader(importlib.machinery.SourceFileLoader):
    """Reads a generator module with `REWRITES` applied (never cached to disk)."""

    def source_to_code(self, data, path, *, _optimize=-1):
        text = data.decode("utf-8")
        for pattern, new in REWRITES:
            text = pattern.sub(new, text)
        return compile(text, path, "exec", dont_inherit=True)

    def get_code(self, fullname):
        return self.source_to_code(self.get_data(self.get_filename(fullname)), self.path)


class _UpstreamFinder(importlib.abc.MetaPathFinder):
    """Finds the generator's own packages (`Features`, `Utils`, `OCCUtils`, ...) in its folder."""

    def __init__(self, root):
        self.finder = importlib.machinery.FileFinder(
            str(root), (_UpstreamLoader, importlib.machinery.SOURCE_SUFFIXES)
        )
        self.root = root

    def find_spec(self, fullname, path=None, target=None):
        top = fullname.split(".")[0]
        if not (self.root / top).exists() and not (self.root / f"{top}.py").exists():
            return None
        if "." not in fullname:
            return self.finder.find_spec(fullname, target)
        parent = sys.modules[fullname.rsplit(".", 1)[0]]
        sub = importlib.machinery.FileFinder(
            parent.__path__[0], (_UpstreamLoader, importlib.machinery.SOURCE_SUFFIXES)
        )
        return sub.find_spec(fullname, target)


def _pythonocc_out_parameters():
    """pythonocc returns a C++ function's out-parameters with its result; OCP drops them."""
    from OCP.BRep import BRep_Tool

    def curve(edge, *rest):
        if rest:
            return BRep_Tool.Curve_s(edge, *rest)
        first, last = BRep_Tool.Range_s(edge)
        return BRep_Tool.Curve_s(edge, first, last), first, last

    BRep_Tool.Curve = staticmethod(curve)


def _pythonocc_equality():
    from OCP.TopoDS import TopoDS_Shape

    def eq(a, b):
        return isinstance(b, TopoDS_Shape) and a.IsEqual(b)

    def ne(a, b):
        return not eq(a, b)

    hash_of = TopoDS_Shape.__hash__
    TopoDS_Shape.__eq__ = eq
    TopoDS_Shape.__ne__ = ne
    TopoDS_Shape.__hash__ = hash_of


def install(upstream_dir):
    """Make `import OCC...` and the generator's modules in `upstream_dir` importable."""
    from pathlib import Path

    root = Path(upstream_dir).resolve()
    if not (root / "feature_creation.py").exists():
        raise FileNotFoundError(f"{root}: not the MFCAD++ generator (no feature_creation.py)")
    _pythonocc_equality()
    _pythonocc_out_parameters()
    sys.meta_path.insert(0, _UpstreamFinder(root))
    sys.meta_path.insert(0, _OccFinder())
