"""Imports every given NumPy module (the golden files in generated/) and calls its _offset on a
scalar and on an array: each must give a finite float64 of the right shape. Exits 1 naming the
modules that fail.

usage: import_modules.py MODULE.py ...
"""
import importlib.util
import os
import sys

import numpy as np

failed = []
for path in sys.argv[1:]:
    prefix = os.path.splitext(os.path.basename(path))[0]
    try:
        spec = importlib.util.spec_from_file_location(prefix, path)
        module = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(module)
        offset = getattr(module, prefix + "_offset")
        scalar = offset(0.1, 0.2, 0.3, 0.05)
        array = offset(np.linspace(0, 1, 7), 0.2, 0.3, 0.05)
        assert isinstance(scalar, np.float64) and np.isfinite(scalar), f"scalar result {scalar!r}"
        assert array.shape == (7,) and array.dtype == np.float64 and np.all(np.isfinite(array)), f"array {array!r}"
    except Exception as e:  # noqa: BLE001 - report every module, then fail
        failed.append(f"{path}: {type(e).__name__}: {e}")
print(f"{len(sys.argv) - 1 - len(failed)} of {len(sys.argv) - 1} modules import and evaluate")
for line in failed:
    print(line)
sys.exit(1 if failed or len(sys.argv) < 2 else 0)
