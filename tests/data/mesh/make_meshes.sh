#!/usr/bin/env bash
# Makes the mesh test data with REAL Radiance 5.4a's obj2mesh (a developer's
# tool; the tests only read what it writes). Run from anywhere:
#   tests/data/mesh/make_meshes.sh [RADIANCE_DIR]
# obj2mesh writes its own command line into the header, so it is run from this
# folder with relative names: the headers do not depend on where the checkout is.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
rad=${1:-$here/../../../../shared/reference/radiance-5.4a}
export PATH=$rad/bin:$PATH RAYPATH=.:$rad/lib
cd "$here"

# radiance-functions.md §13.3's worked example: two triangles with vt and vn,
# materials red (a light modified by the pattern uvf) and blue.
obj2mesh -a mats.rad tri.obj tri.rtm
# §13.6 item 6: the same faces without vt/vn.
obj2mesh -a mats.rad tri_flat.obj tri_flat.rtm
# No material file: every triangle is void (material index -1) and the
# material section is empty.
obj2mesh tri_flat.obj tri_void.rtm
# Enough triangles for several patches and joiner triangles, four materials
# (one of them a pattern), vertices with and without (u,v).
python3 make_bumpy_sphere.py
obj2mesh -a mats.rad -a grey.rad bumpy_sphere.obj bumpy_sphere.rtm
# The fuzzer's multi-patch seed (tests/fuzz/corpus/mesh/grid.rtm): a 17x17
# grid, 289 vertices, so two patches and joiners in a small file.
obj2mesh grid.obj grid.rtm
cp grid.rtm ../../fuzz/corpus/mesh/grid.rtm
