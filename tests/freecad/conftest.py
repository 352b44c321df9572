"""pytest configuration of the workbench tests (headless FreeCAD, real OCCT).

Paths: FreeCAD's library (freecad-python3), the workbench (plugin/C2Blend) and the
built c2blend module (C2B_MODULE_DIR, set by ctest). HOME is a temporary folder so no
user configuration is left behind.
"""
import os
import sys
import tempfile

os.environ["HOME"] = tempfile.mkdtemp(prefix="c2b_fc_home_")
HERE = os.path.dirname(os.path.abspath(__file__))
for p in ("/usr/lib/freecad-python3/lib", os.path.join(HERE, "..", "..", "plugin", "C2Blend"),
          os.environ.get("C2B_MODULE_DIR", "")):
    if p and p not in sys.path:
        sys.path.append(p)

import FreeCAD  # noqa: E402,F401  (FreeCAD must be imported before Part)


def pytest_collection_modifyitems(config, items):
    """Keep one shard of the suite when C2B_SHARD is "k/n" (1 <= k <= n).

    ctest runs the suite as n tests so each stays within its timeout and two run at once;
    the shards take every n-th test in collection order, so neighbouring tests, which
    tend to cost alike, spread over all shards.
    """
    shard = os.environ.get("C2B_SHARD")
    if not shard:
        return
    try:
        k, n = (int(s) for s in shard.split("/"))
    except ValueError:
        raise ValueError("C2B_SHARD must be k/n, e.g. 2/4, not %r" % shard) from None
    if not 1 <= k <= n:
        raise ValueError("C2B_SHARD %r: k must be in 1..n" % shard)
    kept = [it for i, it in enumerate(items) if i % n == k - 1]
    dropped = [it for i, it in enumerate(items) if i % n != k - 1]
    if dropped:
        config.hook.pytest_deselected(items=dropped)
    items[:] = kept
