"""pip install ./client/python: the getme package, with getme/v1/*_pb2.py generated from the
repository's proto/getme/v1 in the build_py step (never committed, never hand-edited).

Offline on Debian (pip is PEP 668 externally managed, so into a venv that sees the system's
grpcio, protobuf and numpy):

    /usr/bin/python3 -m venv --system-site-packages /tmp/venv
    PIP_NO_INDEX=1 /tmp/venv/bin/pip install ./client/python

There is deliberately no pyproject.toml: with one, pip 23 builds in an isolated environment and
downloads setuptools for it, which fails offline (short of --no-build-isolation); without one it
uses the setuptools and wheel the venv already sees.

Needs protoc matching the Python protobuf runtime and grpc_python_plugin (Debian:
protobuf-compiler, protobuf-compiler-grpc); GETME_PROTOC and GETME_GRPC_PYTHON_PLUGIN override
their paths, GETME_PROTO_DIR the proto directory (default: ../../proto, or ./proto beside this
file).
"""

import os
import subprocess

from setuptools import setup
from setuptools.command.build_py import build_py

HERE = os.path.dirname(os.path.abspath(__file__))
PROTOS = ("mesh", "params", "quality", "smoother")


def proto_dir():
    candidates = [os.environ.get("GETME_PROTO_DIR"), os.path.join(HERE, "proto"),
                  os.path.join(HERE, os.pardir, os.pardir, "proto")]
    for candidate in candidates:
        if candidate and os.path.isfile(os.path.join(candidate, "getme", "v1", "smoother.proto")):
            return os.path.abspath(candidate)
    raise SystemExit("getme: proto/getme/v1/*.proto not found (looked in "
                     f"{', '.join(c for c in candidates if c)}); set GETME_PROTO_DIR")


def generate_modules(out_dir):
    """protoc --python_out/--grpc_out into out_dir: the proto package getme.v1 lands in
    out_dir/getme/v1, inside this package."""
    protoc = os.environ.get("GETME_PROTOC", "/usr/bin/protoc")
    plugin = os.environ.get("GETME_GRPC_PYTHON_PLUGIN", "/usr/bin/grpc_python_plugin")
    for tool, package in ((protoc, "protobuf-compiler"), (plugin, "protobuf-compiler-grpc")):
        if not os.path.isfile(tool):
            raise SystemExit(f"getme: {tool} not found (Debian: apt install {package})")
    source = proto_dir()
    protos = [os.path.join(source, "getme", "v1", f"{name}.proto") for name in PROTOS]
    subprocess.run([protoc, f"-I{source}", f"--python_out={out_dir}", f"--grpc_out={out_dir}",
                    f"--plugin=protoc-gen-grpc={plugin}"] + protos, check=True)


class BuildPyWithModules(build_py):
    """build_py, then the generated getme.v1 modules into the build directory (not the source
    tree)."""

    def run(self):
        super().run()
        if not self.dry_run:
            generate_modules(self.build_lib)


setup(
    name="getme",
    version="0.1.0",
    description="Client of getme-server: GETMe smoothing of mixed volume meshes over gRPC",
    packages=["getme", "getme.v1"],
    python_requires=">=3.9",
    # Debian's python3-grpcio, python3-protobuf and python3-numpy provide these; meshio is
    # optional (python3-meshio), for meshio.Mesh input.
    install_requires=["grpcio", "protobuf", "numpy"],
    extras_require={"meshio": ["meshio"]},
    cmdclass={"build_py": BuildPyWithModules},
)
