#!/usr/bin/env bash
# Runs the README's quick start on a pristine Debian 12 root, as a new user
# on a freshly installed machine would: builds the root with debootstrap,
# copies a clean clone of HEAD into it, and runs the README's commands inside
# it with chroot, printing each command's wall time and exit code.
#
# Not part of .ci/run (a cold build of everything takes most of an hour on two
# cores). Run it before resolving anything that touches the build or the
# dependencies.
#
# usage: tools/check-fresh-machine.sh [--keep] [--only-render]
#   --keep         leave the root in place afterwards (default: removed)
#   --only-render  stop after `make render`
# environment:
#   FRESH_ROOT     where the root is built (default /var/tmp/femto-fresh-root;
#                  anything already there is removed first)
#   FRESH_MIRROR   the Debian mirror debootstrap uses (default: the first
#                  bookworm mirror in this machine's apt sources)
# Needs root (debootstrap, chroot, mounts) and reach of a Debian mirror.
set -euo pipefail

keep=0
only_render=0
for arg in "$@"; do
  case "$arg" in
    --keep) keep=1 ;;
    --only-render) only_render=1 ;;
    -h|--help) sed -n '2,20p' "$0"; exit 0 ;;
    *) echo "error: unknown argument '$arg' (see --help)" >&2; exit 2 ;;
  esac
done

if [ "$(id -u)" -ne 0 ]; then
  echo "error: needs root (debootstrap, chroot and bind mounts)" >&2
  exit 1
fi

repo="$(cd "$(dirname "$0")/.." && pwd)"
root="${FRESH_ROOT:-/var/tmp/femto-fresh-root}"
log_dir="${repo}/build/fresh-machine"
mkdir -p "$log_dir"

# The mirror: whatever this machine's apt already uses, so the check needs no
# host name of its own.
mirror="${FRESH_MIRROR:-}"
if [ -z "$mirror" ]; then
  mirror=$( (cat /etc/apt/sources.list.d/*.sources 2>/dev/null || true) | awk '
      /^URIs:/ { uri = $2 }
      /^Suites:/ { for (i = 2; i <= NF; i++) if ($i == "bookworm" && uri != "") { print uri; exit } }')
fi
if [ -z "$mirror" ] && [ -f /etc/apt/sources.list ]; then
  mirror=$(awk '$1 == "deb" && $3 == "bookworm" { print $2; exit }' /etc/apt/sources.list)
fi
if [ -z "$mirror" ]; then
  echo "error: no bookworm mirror in /etc/apt/sources*; set FRESH_MIRROR" >&2
  exit 1
fi

if ! command -v debootstrap >/dev/null; then
  echo "== installing debootstrap on this machine (a tool of the check, not of femto)"
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq debootstrap >/dev/null
fi

if [ -n "$(git -C "$repo" status --porcelain --untracked-files=no)" ]; then
  echo "warning: the work tree has uncommitted changes; the check uses HEAD only" >&2
fi
head_commit=$(git -C "$repo" rev-parse --short HEAD)

mounted=()
cleanup() {
  local i
  for ((i = ${#mounted[@]} - 1; i >= 0; i--)); do
    umount -l "${mounted[$i]}" 2>/dev/null || true
  done
  if [ "$keep" -eq 0 ] && [ -d "$root" ]; then
    rm -rf --one-file-system "$root"
  fi
}
trap cleanup EXIT

# One timed step: prints its wall time and exit code, and keeps going so the
# summary shows every step.
results=()
timed() {
  local name="$1"; shift
  local logfile="$log_dir/$(echo "$name" | tr -c 'a-zA-Z0-9\n' '_').log"
  echo "== $name  (log: $logfile)"
  local start end rc
  start=$(date +%s)
  set +e
  "$@" >"$logfile" 2>&1
  rc=$?
  set -e
  end=$(date +%s)
  local secs=$((end - start))
  local line
  line=$(printf '%-48s exit %3d  wall %2dm%02ds' "$name" "$rc" $((secs / 60)) $((secs % 60)))
  echo "   $line"
  results+=("$line")
  if [ "$rc" -ne 0 ]; then
    echo "   last lines of the log:"
    tail -n 25 "$logfile" | sed 's/^/   | /'
  fi
  return "$rc"
}

summary() {
  echo
  echo "== fresh-machine check of $head_commit ($(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores)"
  local r
  for r in "${results[@]}"; do echo "   $r"; done
}

if [ -e "$root" ]; then
  rm -rf --one-file-system "$root"
fi
mkdir -p "$root"

# Debian's default variant: the required and important packages, which is
# what a fresh installation without desktop has.
if ! timed "debootstrap bookworm" debootstrap bookworm "$root" "$mirror"; then
  summary; exit 1
fi

cp /etc/resolv.conf "$root/etc/resolv.conf"
# The same apt sources as this machine (updates and security included).
if ls /etc/apt/sources.list.d/*.sources >/dev/null 2>&1; then
  cp /etc/apt/sources.list.d/*.sources "$root/etc/apt/sources.list.d/"
  : >"$root/etc/apt/sources.list"
fi
for m in proc sys dev dev/pts; do
  mkdir -p "$root/$m"
  mount --bind "/$m" "$root/$m"
  mounted+=("$root/$m")
done

# A clean clone of HEAD: nothing built, nothing untracked.
git clone --quiet --no-hardlinks "$repo" "$root/root/femto"
git -C "$root/root/femto" checkout --quiet "$head_commit"
rm -rf "$root/root/femto/.git"
# Tests may read ../shared when present, as in CI.
if [ -d "$repo/../shared" ]; then
  cp -a "$repo/../shared" "$root/root/shared"
fi

in_root() {
  chroot "$root" /usr/bin/env -i HOME=/root TERM=dumb LANG=C.UTF-8 \
    PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin \
    /bin/bash -c "cd /root/femto && $1"
}

status=0
# The README's prerequisite: make itself (a fresh Debian 12 has none).
timed "apt-get install make (README prerequisite)" \
  in_root "apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq make" || status=1
if [ "$status" -eq 0 ]; then
  timed "make render" in_root "make render" || status=1
  if [ "$status" -eq 0 ]; then
    in_root "test -s out/cornell-box.exr && test -s out/cornell-box.png" ||
      { echo "error: make render wrote no out/cornell-box.exr/.png" >&2; status=1; }
    built_tests=$(in_root "ls build/bin | grep -c -E 'test' || true")
    echo "   test executables built by make render: $built_tests"
    [ "$built_tests" -eq 0 ] || { echo "error: make render built test executables" >&2; status=1; }
  fi
fi
if [ "$status" -eq 0 ] && [ "$only_render" -eq 0 ]; then
  timed "make test" in_root "make test" || status=1
  grep -E 'tests passed|tests failed' "$log_dir/make_test.log" | tail -1 | sed 's/^/   /' || true
fi
summary
exit "$status"
