"""getme.read / getme.write: mesh files in the formats the getme CLI reads and writes, as
meshio.Mesh objects.

Why through the CLI rather than meshio's own readers: the CLI's readers are the ones the rest of
the product uses, so a file means the same thing to Python as to `getme smooth`. meshio lacks some
of them (OpenFOAM polyMesh) and reads others differently: an SU2 file's mirror-numbered elements
(docs/formats.md, "SU2") stay inverted in meshio, while getme renumbers them on read. The CLI
converts to and from a VTK XML file in a temporary directory, which meshio reads and writes with
every cell, point and cell array kept (meshio's VTU reader and writer are the best-kept ones it
has); the neutral model is the same, VTK cells with named arrays (docs/formats.md).

The CLI is found as the `cli` argument, else the GETME_CLI environment variable, else `getme` on
PATH. meshio is needed here only (the rest of the package never imports it).
"""

from __future__ import annotations

import os
import shutil
import subprocess
import tempfile
from typing import Optional


class FileError(Exception):
    """The CLI could not read or write a file: .path is the file, .message the CLI's own error
    (which names the line, section or field)."""

    def __init__(self, path: str, message: str):
        super().__init__(f"{path}: {message}" if message else path)
        self.path = path
        self.message = message


def _cli_path(cli: Optional[str]) -> str:
    candidate = cli or os.environ.get("GETME_CLI") or shutil.which("getme")
    if not candidate:
        raise FileNotFoundError(
            "the getme CLI was not found: pass cli=PATH, set GETME_CLI, or put `getme` on PATH "
            "(build/bin/getme after scripts/build.sh)")
    return candidate


def _convert(cli: Optional[str], source: str, target: str, reported_path: str,
             options: list) -> str:
    command = [_cli_path(cli), "convert", source, target, *options]
    finished = subprocess.run(command, capture_output=True, text=True, check=False)
    if finished.returncode == 2:
        # A usage error: the options given here, not the file (e.g. an unknown format name).
        raise ValueError(finished.stderr.strip())
    if finished.returncode != 0:
        raise FileError(reported_path, finished.stderr.strip())
    return finished.stderr


def read(path: str, *, file_format: Optional[str] = None, cli: Optional[str] = None):
    """Reads a mesh file (any format `getme convert` reads: .vtk, .vtu, .msh, .mesh, and the
    formats docs/formats.md lists) into a meshio.Mesh, with its tags and arrays as cell and point
    data under meshio's names (gmsh:physical, medit:ref, ...).

    file_format: the CLI's --input-format name, when neither the extension nor the content
      tells. Raises FileNotFoundError for a missing path, getme.FileError naming the file and
      what is wrong in it for a file the CLI refuses, ValueError for an unknown format name.
    """
    import meshio

    if not os.path.exists(path):
        raise FileNotFoundError(f"{path}: no such file or directory")
    with tempfile.TemporaryDirectory(prefix="getme-read-") as work:
        converted = os.path.join(work, "mesh.vtu")
        options = ["--binary"]
        if file_format:
            options += ["--input-format", file_format]
        _convert(cli, path, converted, path, options)
        return meshio.read(converted)


def write(path: str, mesh, *, file_format: Optional[str] = None, binary: Optional[bool] = None,
          cli: Optional[str] = None) -> None:
    """Writes a meshio.Mesh to `path` in the format its extension (or file_format, the CLI's
    --format name) names, as `getme convert` writes it.

    binary: True / False for the output encoding where the format has both; None: the format's
      default for a binary input. Raises getme.FileError naming the file and the CLI's message
      when the mesh cannot be written in that format, ValueError for an unknown format name.
    """
    import meshio

    with tempfile.TemporaryDirectory(prefix="getme-write-") as work:
        staged = os.path.join(work, "mesh.vtu")
        meshio.write(staged, mesh, binary=True)
        options = []
        if file_format:
            options += ["--format", file_format]
        if binary is not None:
            options.append("--binary" if binary else "--ascii")
        _convert(cli, staged, path, path, options)
