# The host package's tests (docs/host.md): they import sw/host/hwinterp_host
# from the source tree, so they run whether or not the package is installed.
import os
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "sw", "host"))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
