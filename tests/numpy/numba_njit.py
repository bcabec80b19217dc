"""Every function of a generated NumPy module compiles under numba.njit and agrees with the plain
NumPy call: on scalars, on 1-D arrays of one shape (with a scalar h or t), and through
numba.vectorize with broadcasting (the module docstring's recipe). Exits 1 on any difference above
1e-12 (relative to max(1, |value|)).

usage: numba_njit.py MODULE.py
"""
import importlib.util
import inspect
import os
import sys

import numpy as np

try:
    import numba
except ImportError:
    sys.exit("numba is not installed (Debian: python3-numba; run tools/install_deps.sh)")

path = sys.argv[1]
prefix = os.path.splitext(os.path.basename(path))[0]
spec = importlib.util.spec_from_file_location(prefix, path)
module = importlib.util.module_from_spec(spec)
spec.loader.exec_module(module)

failed = False


def compare(label, jit_value, np_value):
    global failed
    a = np.stack(np.broadcast_arrays(*jit_value), -1) if isinstance(jit_value, tuple) else np.asarray(jit_value)
    b = np.stack(np.broadcast_arrays(*np_value), -1) if isinstance(np_value, tuple) else np.asarray(np_value)
    same_nan = np.array_equal(np.isnan(a), np.isnan(b))
    finite = ~np.isnan(b)
    worst = float(np.max(np.abs(a[finite] - b[finite]) / np.maximum(1.0, np.abs(b[finite])), initial=0.0))
    ok = same_nan and a.shape == b.shape and worst <= 1e-12
    failed = failed or not ok
    print(f"{label:<50} shape {str(a.shape):<12} max {worst:.2e} {'ok' if ok else 'FAIL'}")


rng = np.random.default_rng(7)
with np.errstate(all="ignore"):
    for name in module.__all__:
        function = getattr(module, name)
        params = list(inspect.signature(function).parameters)
        jitted = numba.njit(function)
        if params[0] == "x":
            scalars = [0.13, 0.71, 0.42, 0.05][: len(params)]
            arrays = [rng.uniform(0, 1, 1000) for _ in params]
            arrays[-1] = 0.05 if params[-1] in ("h", "t") else arrays[-1]  # one shape, or a scalar
        else:
            scalars = [0.1]
            arrays = [np.linspace(-0.1, 1.1, 1000)]
        compare(f"{name} njit scalars", jitted(*scalars), function(*scalars))
        compare(f"{name} njit arrays", jitted(*arrays), function(*arrays))
        if not name.endswith("_normal"):
            signature = "float64(" + ", ".join(["float64"] * len(params)) + ")"
            ufunc = numba.vectorize([signature])(function)
            grid = [rng.uniform(0, 1, (17, 1, 1)), rng.uniform(0, 1, (1, 9, 1)), rng.uniform(0, 1, (1, 1, 5)), 0.05]
            broadcast = grid[: len(params)] if params[0] == "x" else [np.linspace(-0.1, 1.1, 50)]
            compare(f"{name} numba.vectorize broadcast", ufunc(*broadcast), function(*broadcast))
sys.exit(1 if failed else 0)
