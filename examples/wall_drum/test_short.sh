#!/bin/bash
# ctest example.drum_field_short: the drum of in.drum_field (1,048 dodecahedra,
# 0.3 m, 45 rpm, mu 0.7) for 0.75 revolution (the full run's spin-up; after
# 0.4 revolution the bed still overshoots, 84.5 deg), then its field averaged
# over 0.15 revolution (21 snapshots; about 2 minutes on one core), in a
# scratch folder;
# velocity_field.py's figures checked against the regime the full runs show
# (README: 0.75 revolution, and 0.25 at dt 8e-6 s):
#   - 1048 grains kept (lost atoms are an error);
#   - the bed is lifted: carried up the rising wall beyond 120 deg from the
#     bottom (full runs: 160-174 deg);
#   - cataracting: 5-30 % of the grain samples in flight (full: 13.3-17.6 %);
#   - bed angle from the centre of mass 50-72 deg (full: 57.9-64.5 deg over
#     0.25-0.75 revolution; the window moves it most).
# Usage: test_short.sh LMP
set -euo pipefail
# shellcheck source=SCRIPTDIR/../scratch.sh
. "$(dirname "$0")/../scratch.sh"    # here: this folder; scratch: removed on exit
cd "$scratch"
cp "$here/drum_big.stl" .
"$1" -in "$here/in.drum_field" -screen none -log log.short -var pot "$here/../../potentials" \
  -var nspin 0.75 -var navg 0.15
/usr/bin/python3 "$here/velocity_field.py" drum_field.dump --png field.png --summary summary.txt > /dev/null
cat summary.txt
/usr/bin/python3 - <<'PY'
import re
import sys
s = open("summary.txt").read()
log = open("log.short").read()
atoms = int(re.findall(r"^\s*\d+\s+\S+\s+\S+\s+(\d+)\s", log, re.M)[-1])
lift = float(re.search(r"carried up the rising wall to ([\d.]+) deg", s).group(1))
fly = float(re.search(r"in flight above the bed\): ([\d.]+) %", s).group(1))
ang = float(re.search(r"bed angle from the centre of mass .*: ([\d.]+) deg", s).group(1))
checks = [("1048 grains kept (%d)" % atoms, atoms == 1048),
          ("bed carried beyond 120 deg (%.0f)" % lift, lift > 120.0),
          ("5-30 %% of samples in flight (%.1f)" % fly, 5.0 <= fly <= 30.0),
          ("bed angle 50-72 deg (%.1f)" % ang, 50.0 <= ang <= 72.0)]
for name, ok in checks:
    print(("ok   " if ok else "FAIL ") + name)
sys.exit(0 if all(ok for _, ok in checks) else 1)
PY
