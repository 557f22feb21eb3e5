"""Lets `/usr/bin/python3 -c "import heavesim"` work from the repository root after
scripts/build.sh: the package is built into <build>/python/heavesim (the build directory
is $HEAVESIM_BUILD_DIR, default build/), which this puts on sys.path before importing
it in this module's place. Elsewhere, set PYTHONPATH=<repository>/build/python
(docs/python.md)."""
import os
import sys

_package_parent = os.path.join(os.path.dirname(os.path.abspath(__file__)),
                               os.environ.get("HEAVESIM_BUILD_DIR", "build"), "python")
if not os.path.isdir(os.path.join(_package_parent, "heavesim")):
    raise ImportError(f"the heavesim package is not built ({_package_parent}/heavesim is missing): "
                      "run scripts/build.sh first (docs/python.md)")
sys.path.insert(0, _package_parent)
del sys.modules[__name__]
import heavesim  # noqa: E402,F401  the package; the import system returns it for this module
