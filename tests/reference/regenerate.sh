#!/bin/bash
# Regenerates data/*.txt with the reference Yade (apt-get install -y yade).
set -euo pipefail
cd "$(dirname "$0")"
for s in bouncing_sphere oblique_impact; do
    yade -n -x -j1 "$s.py" 2>/dev/null | grep -E '^[0-9]+ [0-9]+ ' > "data/$s.txt"
done
# the FrictVisco law's scenes (tests/test_frictvisco.py): one JSON line
yade -n -x -j1 frictvisco.py 2>/dev/null | grep '^FRICTVISCO ' | sed 's/^FRICTVISCO //' > data/frictvisco.json
# the periodic scenes (tests/test_periodic.py): one JSON line
yade -n -x -j1 periodic.py 2>/dev/null | grep '^PERIODIC ' | sed 's/^PERIODIC //' > data/periodic.json
# tutorial 04's deterministic copy (tests/test_tutorials.py): the series it saves
tmp=$(mktemp -d) && python3 tutorial04_copy.py > "$tmp/t.py" && (cd "$tmp" && yade -n -x -j1 t.py >/dev/null 2>&1) && cp "$tmp"/2*.txt data/tutorial04.txt && rm -rf "$tmp"
# the periodic cell controllers (tests/test_peri_controllers.py): one JSON line
yade -n -x -j1 peri_controllers.py 2>/dev/null | grep '^PERICONTROLLERS ' | sed 's/^PERICONTROLLERS //' > data/peri_controllers.json
# Peri3dController (tests/test_peri3d.py): one JSON line
yade -n -x -j1 peri3d.py 2>/dev/null | grep '^PERI3D ' | sed 's/^PERI3D //' > data/peri3d.json
# clumps (tests/test_clump.py): one JSON line
yade -n -x -j1 clump.py 2>/dev/null | grep '^CLUMP ' | sed 's/^CLUMP //' > data/clump.json
# clumps on the packing side (tests/test_clump_packing.py): one JSON line
yade -n -x -j1 clump_packing.py 2>/dev/null | grep '^CLUMPPACK ' | sed 's/^CLUMPPACK //' > data/clump_packing.json
# aspherical rotation, Fincham's scheme (tests/test_aspherical_rotation.py): one JSON line
yade -n -x -j1 aspherical.py 2>/dev/null | grep '^ASPHERICAL ' | sed 's/^ASPHERICAL //' > data/aspherical.json
# the families of issue 40, each one JSON line (the tests named in each script's header compare)
yade -n -x -j1 localframe.py 2>/dev/null | grep '^LOCALFRAME ' | sed 's/^LOCALFRAME //' > data/localframe.json
yade -n -x -j1 polyhedra.py 2>/dev/null | grep '^{' > data/polyhedra.json
yade -n -x -j1 cohesive.py 2>/dev/null | grep '^COHESIVE ' | cut -c10- > data/cohesive.json
yade -n -x -j1 triaxial.py 2>/dev/null | grep '^TRIAXIAL' > data/triaxial.json
yade -n -x -j1 cpm.py 2>/dev/null | grep '^CPM ' | sed 's/^CPM //' > data/cpm.json
yade -n -x -j1 pack_dense.py 2>/dev/null | grep '^PACKDENSE ' | sed 's/^PACKDENSE //' > data/pack_dense.json
yade -n -x -j1 grid.py 2>/dev/null | grep '^GRID ' | cut -c6- > data/grid.json
yade -n -x -j1 minieigen_norms.py 2>/dev/null | grep '^{' > data/minieigen_norms.json
