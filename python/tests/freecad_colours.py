"""Run inside FreeCAD (`freecadcmd`) by test_freecad.py: read each part with
FreeCAD, recognize and colour it with the add-on, and write per face what it
set and FreeCAD's own face geometry to a JSON file the test checks.

Its arguments come in environment variables: THINWALL_SYS_PATH (folders to
put on sys.path), THINWALL_PARTS (paths, os.pathsep-separated),
THINWALL_OUT (the JSON file)."""
import json
import os
import sys
import traceback

for folder in os.environ["THINWALL_SYS_PATH"].split(os.pathsep):
    sys.path.insert(0, folder)

out = {"parts": [], "error": None}
try:
    import FreeCAD
    import Part

    import thinwall_freecad

    doc = FreeCAD.newDocument("thinwall")
    for path in os.environ["THINWALL_PARTS"].split(os.pathsep):
        obj = doc.addObject("Part::Feature", "part")
        obj.Shape = Part.read(path)
        result = thinwall_freecad.recognize_object(obj, up=(0, 0, 1))
        # Thinwall's own figures of the same faces (the shape written again).
        inspected = thinwall_freecad.thinwall.inspect(thinwall_freecad.shape_part(obj.Shape))
        out["parts"].append({
            "inspected": inspected.to_dict(),
            "path": path,
            "result": result.to_dict(),
            "kinds": list(obj.ThinwallKinds),
            "colours": [list(c) for c in obj.ThinwallColors],
            "faces": [
                {"area": f.Area, "centroid": list(f.CenterOfMass)} for f in obj.Shape.Faces
            ],
            "freecad": FreeCAD.Version()[:3],
        })
except Exception:
    out["error"] = traceback.format_exc()
with open(os.environ["THINWALL_OUT"], "w") as f:
    json.dump(out, f)
