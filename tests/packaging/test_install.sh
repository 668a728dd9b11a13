#!/usr/bin/env bash
# cmake --install into a fresh prefix; then the installed sedem runs the installed demo scene,
# the man page and bash completion are there and agree with --help, and the Python package
# imports from the prefix, runs a scene in-process and runs the installed sedem.
set -euo pipefail
build=$1 prefix=$2 python=$3 pydir=$4
rm -rf "$prefix"
cmake --install "$build" --prefix "$prefix" > /dev/null
fail() { echo "FAIL: $*"; exit 1; }

exe=$prefix/bin/sedem
[ -x "$exe" ] || fail "no $exe"
"$exe" --version | grep -q . || fail "sedem --version"
for f in share/sedem/scenes/demo.toml share/sedem/scenes/sample1.toml share/doc/sedem/README.md \
  share/doc/sedem/docs/python.md share/doc/sedem/docs/scenes.md share/man/man1/sedem.1 \
  share/bash-completion/completions/sedem "$pydir/sedem/__init__.py" \
  share/sedem/paraview/Macros/sedem_paraview.py; do
  [ -f "$prefix/$f" ] || fail "not installed: $f"
done

# The man page: every command, and every option of every command's --help.
man=$prefix/share/man/man1/sedem.1
grep -q '^\.TH SEDEM 1' "$man" || fail "man page header"
for c in run batch render reduce invert design bench; do
  grep -q "^\.SS sedem $c" "$man" || fail "man page: no section for $c"
  for o in $("$exe" "$c" --help | grep -o -- ' --[a-z][a-z0-9-]*' | sort -u); do
    grep -q -- "$o" "$man" || fail "man page: $c $o missing"
  done
done
if command -v man > /dev/null; then
  MANWIDTH=80 man -l "$man" 2>/dev/null | grep -q "sedem run" || fail "man -l cannot read it"
fi

# Bash completion: commands, and every option each command's --help lists.
completion=$prefix/share/bash-completion/completions/sedem
complete_words() {
  bash -c 'source "$1"; shift; COMP_WORDS=("$@"); COMP_CWORD=$(($# - 1)); _sedem;
           echo "${COMPREPLY[*]}"' _ "$completion" "$@"
}
words=" $(complete_words sedem r) "
for c in run render reduce; do
  [[ $words == *" $c "* ]] || fail "completion of 'sedem r' lacks $c: $words"
done
for c in run batch render reduce invert design; do
  words=" $(complete_words sedem "$c" --) "
  for o in $("$exe" "$c" --help | grep -o -- ' --[a-z][a-z0-9-]*' | sort -u); do
    [[ $words == *" $o "* ]] || fail "completion of 'sedem $c --' lacks $o: $words"
  done
done

# The installed program runs the installed scene (out of the build tree, elsewhere).
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
(cd "$work" && "$exe" run "$prefix/share/sedem/scenes/demo.toml" --quiet \
  --set sample.simulated_count=200 --set run.end_time_s=10 --set output.frames=false) ||
  fail "the installed sedem cannot run the installed demo"
[ -f "$work/out/demo/run.json" ] || fail "no out/demo/run.json"

# The Python package from the prefix, where Debian's python3 looks under /usr/local, with its
# compiled module: a run in the process, and the installed sedem for the rest.
ls "$prefix/$pydir"/sedem/_sedem*.so > /dev/null || fail "no compiled module in $pydir/sedem"
/usr/bin/python3 -c 'import sys; sys.exit(sys.argv[1] not in sys.path)' "/usr/local/$pydir" ||
  fail "/usr/local/$pydir is not on Debian's python3's path"
(cd "$work" && PATH="$prefix/bin:$PATH" PYTHONPATH="$prefix/$pydir" SEDEM_EXE= "$python" -c '
import sys, sedem
assert sedem.__file__.startswith(sys.argv[1]), sedem.__file__
assert sedem.executable() == sys.argv[2], sedem.executable()
run = sedem.load_run("out/demo")
assert run.status == "complete" and run.record["particle_count"] == 200
sim = sedem.simulate(sys.argv[3], set={"sample.simulated_count": 300, "output.frames": False})
assert sim.status == "complete" and len(sim.readings()) > 0
' "$prefix" "$exe" "$prefix/share/sedem/scenes/demo.toml") || fail "the installed Python package"
echo "installed into $prefix: program, scenes, docs, man page, completion, Python package"
