#!/usr/bin/python3
"""Checks the layering of docs/design.md in the sources: what each module may include.

    scripts/check_layers.py [ROOT]

Each rule names a folder and the include prefixes (quoted or in brackets) its C++ files must not
use. The build enforces the same layers through what each CMake target links (CMakeLists.txt,
getme_check_layers); this check also catches a header reached through a path the linker would not
see (e.g. core including a generated getme/v1 header). Exits 1 and names file, line and include
at the first violations.
"""

import pathlib
import re
import sys

# folder -> include prefixes it must not use
FORBIDDEN = {
    # the engine: absl, Eigen, Highway and the standard library only
    "core": ["getme/v1/", "getme_wire/", "getme_server/", "getme_support/", "getme_surface/",
             "remote/", "cli/", "formats/", "events/", "grpcpp/", "google/protobuf/", "spdlog/",
             "CGAL/"],
    # the input's boundary surface: the engine's mesh and CGAL, nothing of the service or files
    "surface": ["getme/v1/", "getme_wire/", "getme_server/", "getme_support/", "remote/", "cli/",
                "formats/", "events/", "grpcpp/", "google/protobuf/", "spdlog/"],
    "support": ["getme/", "getme_wire/", "getme_server/", "remote/", "cli/", "formats/",
                "grpcpp/", "google/protobuf/"],
    # the wire mappings: generated code, the engine, and surface/'s plain-data reports of a
    # sliding boundary and kept layers (wire/getme_wire/boundary_reports.h), never CGAL itself
    "wire": ["getme_server/", "getme_support/", "remote/", "cli/", "formats/", "events/",
             "spdlog/", "getme/meshgen/", "CGAL/"],
    # server and client never include each other
    "server": ["remote/", "cli/", "formats/", "events/"],
    "client": ["getme_server/"],
}
# Quoted and angle-bracket includes: library headers (<grpcpp/...>, <CGAL/...>) come in brackets.
INCLUDE = re.compile(r'^\s*#\s*include\s+["<]([^">]+)[">]')


def violations(root: pathlib.Path):
    for folder, forbidden in FORBIDDEN.items():
        for path in sorted((root / folder).rglob("*")):
            if path.suffix not in (".h", ".cc", ".cpp"):
                continue
            for number, line in enumerate(path.read_text(errors="replace").splitlines(), 1):
                match = INCLUDE.match(line)
                if match and any(match.group(1).startswith(p) for p in forbidden):
                    yield f"{path.relative_to(root)}:{number}: {folder}/ must not include " \
                          f"\"{match.group(1)}\" (docs/design.md, Layers)"


def main(argv):
    root = pathlib.Path(argv[1] if len(argv) > 1 else pathlib.Path(__file__).parent.parent)
    found = list(violations(root))
    for line in found[:20]:
        print(line)
    if found:
        print(f"check_layers: {len(found)} include(s) across layers")
        return 1
    print("check_layers: every include respects the layers")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
