#!/bin/sh
# Stands in for ssh in GNU parallel's --ssh, for tests of --sshlogin with no second machine:
# `fake_ssh.sh [OPTIONS] HOST [--] COMMAND...` runs COMMAND as ssh would on HOST, in a login
# shell's bare surroundings (from /, an environment of PATH, HOME and SHELL only), and appends
# HOST to $FAKE_SSH_LOG when set.
while [ $# -gt 0 ]; do
  case $1 in
    -*) shift ;;
    *) break ;;
  esac
done
host=$1
shift
[ "${1:-}" = "--" ] && shift
[ -n "${FAKE_SSH_LOG:-}" ] && echo "$host" >>"$FAKE_SSH_LOG"
cd / && exec env -i PATH=/usr/local/bin:/usr/bin:/bin HOME=/ SHELL=/bin/sh sh -c "$*"
