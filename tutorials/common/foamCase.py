# dcpRBF. Copyright (C) 2026 the dcpRBF authors. GPL-3.0-or-later (see LICENSE).
"""Helpers of the studies' and benchmarks' scripts: the OpenFOAM environment,
a logged command, an OpenFOAM dictionary file."""
import os
import shutil
import subprocess
import sys

PYTHON = "/usr/bin/python3"
TOP = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))


def foam_env(script, flag="DCPRBF_STUDY_REEXEC"):
    """Re-run script (its __file__) under the project's OpenFOAM environment
    if none is active; flag: the environment variable that marks the re-run."""
    if os.environ.get("WM_PROJECT_DIR") and shutil.which("moveDynamicMesh"):
        return
    rc = os.path.join(TOP, "etc", "bashrc")
    if not os.path.isfile(rc):
        sys.exit("no OpenFOAM environment: run ./Allwmake at the top first")
    if os.environ.get(flag):
        sys.exit("moveDynamicMesh not found after sourcing " + rc)
    os.environ[flag] = "1"
    cmd = 'source "%s" && exec %s "$@"' % (rc, PYTHON)
    os.execvp("bash", ["bash", "-c", cmd, "bash", os.path.abspath(script)] + sys.argv[1:])


def sh(args, cwd, log, env=None):
    """args run in cwd, output and errors to the file log, under env (None:
    this process's); its exit code."""
    with open(log, "w") as f:
        return subprocess.call(args, cwd=cwd, stdout=f, stderr=subprocess.STDOUT, env=env)


HEADER = """FoamFile
{{
    version     2.0;
    format      ascii;
    class       {cls};
    object      {obj};
}}
"""


def write(path, cls, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write(HEADER.format(cls=cls, obj=os.path.basename(path)) + text)
