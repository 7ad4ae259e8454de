#!/usr/bin/env python3
"""Generate the regression-check fixture: the rib-grid panel with its y rib
left out (fixtures/check/rib_grid_panel_one_rib_less.step). `thinwall check`
must tell it from the panel's stored recognition
(fixtures/check/rib_grid_panel.expect.json, written by
`thinwall check fixtures/recognition/rib_grid_panel.step --expect … --update`).

usage: python3 scripts/make_check_fixtures.py [OUT_DIR]   (default fixtures/check)
"""
import os, sys

sys.path.insert(0, os.path.dirname(__file__))
from make_recognition_fixtures import rib_grid_panel, write  # noqa: E402


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "fixtures/check"
    os.makedirs(out, exist_ok=True)
    write(rib_grid_panel(with_y_rib=False), os.path.join(out, "rib_grid_panel_one_rib_less.step"))


if __name__ == "__main__":
    main()
