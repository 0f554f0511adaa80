"""numpy and matplotlib (non-interactive Agg backend) for the benchmark scripts.

    from plot_env import np, plt

A Python ahead of Debian's on PATH (pyenv, venv) may lack the packages: the
importing script is then started again with /usr/bin/python3 (once; the
environment variable CONTACT_DYNAMICS_PLOT_REEXEC marks the second start).
"""
import os
import sys

try:
    import numpy as np
    import matplotlib
except ImportError:
    _system_python = "/usr/bin/python3"
    _script = sys.argv[0] if sys.argv else ""
    if (os.path.exists(_system_python) and os.path.isfile(_script)
            and "CONTACT_DYNAMICS_PLOT_REEXEC" not in os.environ
            and os.path.realpath(sys.executable) != os.path.realpath(_system_python)):
        os.environ["CONTACT_DYNAMICS_PLOT_REEXEC"] = "1"
        os.execv(_system_python, [_system_python] + sys.argv)
    sys.exit(f"{os.path.basename(_script) or 'this script'} needs numpy and matplotlib: "
             "apt-get install -y python3-numpy python3-matplotlib")
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

__all__ = ["np", "matplotlib", "plt"]
