#!/bin/bash
# Issue 17 item 10: with stdout redirected (lmp -in in.x > out.txt), an error
# that aborts (error->one: a data-file check, create_atoms before
# polyhedron_shape, a truncated restart) must still reach out.txt and
# log.lammps. Usage: errors_reach_log.sh LMP
set -u
lmp=$1
dir=$(mktemp -d /tmp/polydem_errlog_XXXXXX)
cd "$dir" || exit 1
pre="units si
atom_style polyhedron
atom_modify map array
region box block -0.05 0.05 -0.05 0.05 -0.05 0.05"
fail=0
check() {    # name, input text, expected message
  printf '%s\n' "$2" > "in.$1"
  rm -f log.lammps
  "$lmp" -in "in.$1" > "out.$1" 2> "err.$1"
  for f in "out.$1" log.lammps; do
    if ! grep -q "ERROR.*$3" "$f" 2>/dev/null; then
      echo "FAIL $1: '$3' not in $f"
      fail=1
    fi
  done
}
check create "$pre
create_box 1 box
create_atoms 1 single 0 0 0" "define a shape with polyhedron_shape"

cat > zero.data <<DATA
test

1 atoms
1 atom types
-0.05 0.05 xlo xhi
-0.05 0.05 ylo yhi
-0.05 0.05 zlo zhi

Atoms

1 1 1 0.01 1000 0 0 0 0 0 0 0
DATA
check data "units si
atom_style polyhedron
polyhedron_shape c $POLYDEM_POTENTIALS/cube.shape
read_data zero.data" "Invalid quaternion"

printf '%s\n' "$pre
create_box 1 box
polyhedron_shape c $POLYDEM_POTENTIALS/cube.shape
create_atoms 1 random 20 4711 NULL
write_restart full.restart" > in.write
"$lmp" -in in.write > out.write 2>&1 || { echo "FAIL: writing the restart"; fail=1; }
head -c $(( $(stat -c %s full.restart) - 200 )) full.restart > cut.restart
check restart "read_restart cut.restart" "restart"
[ $fail = 0 ] && echo "all errors reached the screen and the log"
cd / && rm -rf "$dir"
exit $fail
