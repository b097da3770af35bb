#!/usr/bin/python3
"""`pip install ./client/python` offline into a fresh venv that sees the system's packages (the
documented install path on Debian, whose pip is PEP 668 externally managed), then one smooth call
from that venv against a real getme-server.

The package and the protos are copied first, in the repository's layout (client/python beside
proto/), so pip's in-tree build leaves the source tree alone. pip runs with no index, no
find-links and no configuration file, as on a machine without network.

Usage: test_pip_install.py --source-dir REPO --server-binary getme-server --work-dir DIR
"""

import argparse
import json
import os
import shutil
import subprocess
import sys
import unittest

from server_process import ServerProcess

ARGS = None

# Runs inside the venv: a 2×2×2 hex block whose only interior node (the centre) is displaced.
CLIENT_SCRIPT = r"""
import json, sys
import numpy as np
import getme
points = np.array([(i, j, k) for k in range(3) for j in range(3) for i in range(3)], dtype=float)
points[13] += (0.4, -0.3, 0.2)
def node(i, j, k):
    return (k * 3 + j) * 3 + i
hexahedra = [[node(i, j, k), node(i + 1, j, k), node(i + 1, j + 1, k), node(i, j + 1, k),
              node(i, j, k + 1), node(i + 1, j, k + 1), node(i + 1, j + 1, k + 1),
              node(i, j + 1, k + 1)] for k in range(2) for j in range(2) for i in range(2)]
events = []
(smoothed, cells), report = getme.smooth((points, {"hexahedron": np.array(hexahedra)}),
                                         sys.argv[1], progress=events.append)
import getme.v1.smoother_pb2 as generated
print(json.dumps({"package": getme.__file__, "generated": generated.__file__,
                  "centre": smoothed[13].tolist(), "q_min_before": report.before.q_min,
                  "q_min": report.q_min, "final_event": events[-1].final,
                  "others_kept": bool((np.delete(smoothed, 13, 0) ==
                                       np.delete(points, 13, 0)).all())}))
"""


def offline_environment():
    env = {k: v for k, v in os.environ.items()
           if not k.startswith("PIP_") and k not in ("PYTHONPATH", "PYTHONHOME")}
    env.update(PIP_NO_INDEX="1", PIP_CONFIG_FILE=os.devnull, PIP_DISABLE_PIP_VERSION_CHECK="1",
               PIP_NO_CACHE_DIR="1")
    return env


class PipInstall(unittest.TestCase):
    def test_install_offline_and_smooth(self):
        root = os.path.join(ARGS.work_dir, "pip-install")
        shutil.rmtree(root, ignore_errors=True)
        ignore = shutil.ignore_patterns("build", "*.egg-info", "__pycache__", "*_pb2.py",
                                        "*_pb2_grpc.py")
        shutil.copytree(os.path.join(ARGS.source_dir, "client", "python"),
                        os.path.join(root, "client", "python"), ignore=ignore)
        shutil.copytree(os.path.join(ARGS.source_dir, "proto"), os.path.join(root, "proto"))
        venv = os.path.join(root, "venv")
        env = offline_environment()
        subprocess.run(["/usr/bin/python3", "-m", "venv", "--system-site-packages", venv],
                       check=True, env=env)
        install = subprocess.run([os.path.join(venv, "bin", "pip"), "install", "./client/python"],
                                 cwd=root, env=env, capture_output=True, text=True)
        self.assertEqual(install.returncode, 0, install.stdout + install.stderr)

        # The modules were generated into the build, not into the source tree.
        generated_in_source = [name for name in os.listdir(
            os.path.join(root, "client", "python", "getme", "v1")) if name.endswith(".py")]
        self.assertEqual(generated_in_source, ["__init__.py"])

        server = ServerProcess(ARGS.server_binary, "--progress_interval=0s")
        try:
            run = subprocess.run([os.path.join(venv, "bin", "python"), "-c", CLIENT_SCRIPT,
                                  server.address], cwd=ARGS.work_dir, env=env,
                                 capture_output=True, text=True, timeout=60)
        finally:
            self.assertEqual(server.stop(), 0, "".join(server.log))
        self.assertEqual(run.returncode, 0, run.stderr)
        result = json.loads(run.stdout)
        site_packages = os.path.realpath(os.path.join(venv, "lib"))
        self.assertTrue(os.path.realpath(result["package"]).startswith(site_packages), result)
        self.assertTrue(os.path.realpath(result["generated"]).startswith(site_packages), result)
        # A symmetric block: GETMe takes the centre back to (1, 1, 1) and the cubes to q = 1.
        self.assertLess(max(abs(c - 1.0) for c in result["centre"]), 1e-3, result)
        self.assertGreater(result["q_min"], 0.999)
        self.assertLess(result["q_min_before"], 0.9)
        self.assertTrue(result["others_kept"])
        self.assertTrue(result["final_event"])


if __name__ == "__main__":
    parser = argparse.ArgumentParser()
    parser.add_argument("--source-dir", required=True)
    parser.add_argument("--server-binary", required=True)
    parser.add_argument("--work-dir", required=True)
    ARGS, rest = parser.parse_known_args()
    os.makedirs(ARGS.work_dir, exist_ok=True)
    unittest.main(argv=[sys.argv[0]] + rest, verbosity=2)
