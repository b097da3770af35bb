#!/usr/bin/python3
"""scripts/check_layers.py: a clean tree passes; an include across a layer fails, named."""

import pathlib
import subprocess
import sys
import tempfile

script = sys.argv[1]


def run(files):
    with tempfile.TemporaryDirectory() as root:
        for name, text in files.items():
            path = pathlib.Path(root) / name
            path.parent.mkdir(parents=True, exist_ok=True)
            path.write_text(text)
        return subprocess.run(["/usr/bin/python3", script, root], capture_output=True, text=True)


clean = run({"core/getme/mesh/mesh.h": '#include "getme/elements/element_type.h"\n',
             "wire/getme_wire/a.cc": '#include "getme/v1/mesh.pb.h"\n#include "getme/mesh/mesh.h"\n',
             # The wire carries surface/'s plain-data reports (boundary_reports.h).
             "wire/getme_wire/r.cc": '#include "getme_surface/layer_report.h"\n',
             "server/getme_server/b.cc": '#include "getme_wire/status.h"\n',
             "client/remote/c.cc": '#include "getme_wire/status.h"\n#include "formats/x.h"\n',
             "core/getme/elements/e.h": '#include <Eigen/Core>\n',
             "surface/getme_surface/s.cc": '#include "getme/mesh/mesh.h"\n#include <CGAL/AABB_tree.h>\n'})
assert clean.returncode == 0, clean.stdout

cases = {
    "core/getme/mesh/mesh.cc": ('#include "getme/v1/mesh.pb.h"\n', "core/ must not include"),
    "wire/getme_wire/a.cc": ('\n#include "remote/grid_upload.h"\n', "wire/getme_wire/a.cc:2"),
    "server/getme_server/b.cc": ('#include "cli/failure.h"\n', "server/ must not include"),
    "client/cli/c.cc": ('#include "getme_server/job.h"\n', "client/ must not include"),
    # Library headers come in brackets: the engine must not reach CGAL, whose home is surface/.
    "core/getme/smoothing/s.cc": ('#include <CGAL/AABB_tree.h>\n',
                                  'core/ must not include "CGAL/AABB_tree.h"'),
    "surface/getme_surface/t.cc": ('#include "getme_wire/status.h"\n', "surface/ must not include"),
    # ...but not CGAL, which surface/ keeps private.
    "wire/getme_wire/b.cc": ('#include <CGAL/AABB_tree.h>\n', 'wire/ must not include "CGAL/'),
}
for name, (text, expected) in cases.items():
    bad = run({name: text})
    assert bad.returncode == 1, (name, bad.stdout)
    assert expected in bad.stdout, (name, bad.stdout)
print(f"{1 + len(cases)} passed, 0 failed")
