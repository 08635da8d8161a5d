#!/usr/bin/env bash
# Fresh-machine check: do README.md's two commands work on a minimal Debian 12?
#
#   sudo bash tests/fresh_debian/fresh_debian_root.sh [DIR [REPO]]
#
# Builds a minimal Debian 12 root with debootstrap (--variant=minbase bookworm) in DIR (default
# /tmp/vct-fresh-debian), installs in it only what a newcomer needs to clone (git,
# ca-certificates), clones REPO (default: the repository this script sits in; a clean clone, so
# only committed files count), then runs, from inside the clone and as root in the chroot, the
# command lines of README.md's first ```sh block exactly as written there. No assets are visible
# in the root (no Sponza): the tests that need them skip themselves.
#
# Everything goes to a log file (default /tmp/vct-fresh-debian-<date>.log, or $VCT_FRESH_LOG) and
# the run ends with a PASS/FAIL summary: each command's exit status, the rendered PNG, ctest's
# summary line. Exit status 0 on PASS, 1 on FAIL, 2 on a setup error of the check itself.
#
# Environment:
#   VCT_FRESH_LOG            log file
#   VCT_DEBIAN_MIRROR        Debian mirror (default: the one this machine's apt uses)
#   VCT_FRESH_KEEP_ROOT      1: keep DIR after a PASS too (it is always kept after a FAIL)
#   VCT_FRESH_TIMEOUT        time limit per README command, in seconds (default 10800)
set -uo pipefail

script_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root_dir="${1:-/tmp/vct-fresh-debian}"
repo="${2:-$(git -C "$script_dir" rev-parse --show-toplevel 2>/dev/null || echo "$script_dir/../..")}"
log="${VCT_FRESH_LOG:-/tmp/vct-fresh-debian-$(date -u +%Y%m%d-%H%M%S).log}"
per_command_timeout="${VCT_FRESH_TIMEOUT:-10800}"
marker=".vct-fresh-debian-root"   # written into DIR, so that a later run may delete it
suite=bookworm
clone_in_root=/root/vct           # where the newcomer's clone lives, seen from inside the root

die() { echo "fresh_debian_root: $*" >&2; exit 2; }

[ "$(id -u)" -eq 0 ] || die "run as root (debootstrap, chroot and mount need it): sudo bash $0 ${*:-}"
repo="$(cd "$repo" 2>/dev/null && pwd)" || die "repository not found: ${2:-}"
[ -d "$repo/.git" ] || [ -f "$repo/.git" ] || die "not a git repository: $repo"
case "$root_dir" in /*) ;; *) root_dir="$PWD/$root_dir" ;; esac
root_dir="${root_dir%/}"
[ -n "$root_dir" ] && [ "$root_dir" != / ] || die "refusing DIR=/"

mkdir -p "$(dirname "$log")" && : >"$log" || die "cannot write the log $log"
exec > >(tee -a "$log") 2>&1
started=$(date +%s)
echo "== vct fresh Debian root check, $(date -u '+%Y-%m-%d %H:%M:%S UTC')"
echo "   root: $root_dir"
echo "   repo: $repo (HEAD $(git -C "$repo" rev-parse --short HEAD 2>/dev/null || echo '?'))"
echo "   log:  $log"

stamp() { echo; echo "== [$(date -u +%H:%M:%S), +$(( $(date +%s) - started ))s] $*"; }

# --- mounts, undone on exit whatever happens -----------------------------------------------------
mounted=()
mount_into() {  # mount_into TARGET MOUNT-ARGS...: mount and remember it for the exit trap
  local target="$1"; shift
  mkdir -p "$target"
  mount "$@" "$target" || die "mount $* $target failed"
  mounted+=("$target")
}
kill_root_processes() {  # processes left running inside the root (e.g. a stray Xvfb)
  local p link
  for p in /proc/[0-9]*; do
    link="$(readlink "$p/root" 2>/dev/null)" || continue
    if [ "$link" = "$root_dir" ]; then kill -TERM "${p#/proc/}" 2>/dev/null; fi
  done
  sleep 1
  for p in /proc/[0-9]*; do
    link="$(readlink "$p/root" 2>/dev/null)" || continue
    if [ "$link" = "$root_dir" ]; then kill -KILL "${p#/proc/}" 2>/dev/null; fi
  done
}
cleanup() {
  local i
  [ -d "$root_dir" ] && kill_root_processes
  for ((i = ${#mounted[@]} - 1; i >= 0; i--)); do
    umount "${mounted[i]}" 2>/dev/null || umount -l "${mounted[i]}" 2>/dev/null ||
      echo "fresh_debian_root: could not unmount ${mounted[i]}"
  done
  mounted=()
}
trap cleanup EXIT
trap 'echo "fresh_debian_root: interrupted"; exit 130' INT TERM HUP

# --- the Debian mirror this machine's apt uses ---------------------------------------------------
mirror="${VCT_DEBIAN_MIRROR:-}"
if [ -z "$mirror" ] && [ -f /etc/apt/sources.list.d/debian.sources ]; then
  # deb822: the URIs of the stanza whose Suites include bookworm
  mirror="$(awk -v s="$suite" '
      /^[[:space:]]*$/ { if (ok && uri != "") { print uri; exit } ok = 0; uri = ""; next }
      /^URIs:/ { uri = $2 }
      /^Suites:/ { for (i = 2; i <= NF; i++) if ($i == s) ok = 1 }
      END { if (ok && uri != "") print uri }' /etc/apt/sources.list.d/debian.sources | head -n1)"
fi
if [ -z "$mirror" ] && [ -f /etc/apt/sources.list ]; then
  mirror="$(awk -v s="$suite" '$1 == "deb" && $3 == s { print $2; exit }' /etc/apt/sources.list)"
fi
mirror="${mirror:-http://deb.debian.org/debian}"
security_mirror="$(awk '/^URIs:/ && $2 ~ /security/ { print $2; exit }' /etc/apt/sources.list.d/debian.sources 2>/dev/null)"
security_mirror="${security_mirror:-${mirror%/debian}/debian-security}"
echo "   mirror: $mirror (security: $security_mirror)"

# --- debootstrap ----------------------------------------------------------------------------------
if ! command -v debootstrap >/dev/null; then
  stamp "installing debootstrap on this machine"
  DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends debootstrap ||
    { apt-get update -q && DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends debootstrap; } ||
    die "cannot install debootstrap"
fi

if [ -e "$root_dir" ]; then
  if [ -f "$root_dir/$marker" ]; then
    stamp "removing the previous root $root_dir"
    kill_root_processes
    # a previous run that was killed hard may have left its mounts
    for m in dev/shm dev/pts dev sys proc; do
      mountpoint -q "$root_dir/$m" && { umount "$root_dir/$m" || umount -l "$root_dir/$m"; }
    done
    rm -rf --one-file-system "$root_dir" || die "cannot remove $root_dir"
  elif [ -n "$(ls -A "$root_dir" 2>/dev/null)" ]; then
    die "$root_dir exists, is not empty and was not made by this script; give an empty or new DIR"
  fi
fi
mkdir -p "$root_dir" && touch "$root_dir/$marker" || die "cannot create $root_dir"

stamp "debootstrap --variant=minbase $suite $root_dir $mirror"
debootstrap --variant=minbase "$suite" "$root_dir" "$mirror" || die "debootstrap failed"

# What a Debian 12 installation's apt knows: the release, its updates and security updates.
cat >"$root_dir/etc/apt/sources.list" <<EOF
deb $mirror $suite main
deb $mirror $suite-updates main
deb $security_mirror $suite-security main
EOF
cp -L /etc/resolv.conf "$root_dir/etc/resolv.conf" 2>/dev/null || true
# Standard for chroots: packages must not start daemons on the host.
printf '#!/bin/sh\nexit 101\n' >"$root_dir/usr/sbin/policy-rc.d" && chmod 755 "$root_dir/usr/sbin/policy-rc.d"

# --- the kernel file systems the build and the tests use ------------------------------------------
mount_into "$root_dir/proc" -t proc proc
mount_into "$root_dir/sys" -t sysfs sysfs
mount_into "$root_dir/dev" --bind /dev
mount --make-private "$root_dir/dev" 2>/dev/null || true   # so the mounts below stay in the root
mount_into "$root_dir/dev/pts" --bind /dev/pts
mount_into "$root_dir/dev/shm" -t tmpfs -o mode=1777,nosuid,nodev shm   # POSIX shared memory (Mesa, Xvfb)

# Run a command inside the root with a clean login-like environment (no DISPLAY, no VCT_* from here).
in_root() {
  chroot "$root_dir" /usr/bin/env -i HOME=/root USER=root LOGNAME=root SHELL=/bin/bash TERM=dumb \
    LANG=C.UTF-8 PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin "$@"
}

stamp "installing what a newcomer needs to clone: git ca-certificates"
in_root apt-get update -q || die "apt-get update in the root failed"
in_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends git ca-certificates ||
  die "installing git in the root failed"

# --- the clone: committed files only ---------------------------------------------------------------
stamp "git clone $repo (inside the root)"
mount_into "$root_dir/mnt/origin" --bind "$repo"
mount -o remount,bind,ro "$root_dir/mnt/origin" 2>/dev/null || true
# (safe.directory: the origin may belong to another user than root.)
in_root git -c safe.directory='*' clone --no-hardlinks /mnt/origin "$clone_in_root" || die "git clone failed"
in_root git -C "$clone_in_root" log -1 --format='   cloned commit %h %cd %s' --date=iso
umount "$root_dir/mnt/origin" && mounted=("${mounted[@]:0:${#mounted[@]}-1}")
clone="$root_dir$clone_in_root"

# --- README.md's commands ---------------------------------------------------------------------------
mapfile -t commands < <(awk '/^```sh[[:space:]]*$/ { inside = 1; next }
                              inside && /^```/ { exit }
                              inside && NF { print }' "$clone/README.md")
((${#commands[@]})) || die "no \`\`\`sh block with commands in README.md"
echo "   README.md's first sh block: ${#commands[@]} command lines"

statuses=()
for i in "${!commands[@]}"; do
  stamp "README command $((i + 1)) of ${#commands[@]}, in $clone_in_root:"
  echo "   \$ ${commands[i]}"
  command_started=$(date +%s)
  timeout --kill-after=60 "$per_command_timeout" \
    chroot "$root_dir" /usr/bin/env -i HOME=/root USER=root LOGNAME=root SHELL=/bin/bash TERM=dumb \
      LANG=C.UTF-8 PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin \
      /bin/bash -c 'cd "$1" || exit 1; eval "$2"' bash "$clone_in_root" "${commands[i]}" </dev/null
  statuses+=($?)
  echo "== README command $((i + 1)) exit status ${statuses[i]} after $(( $(date +%s) - command_started ))s"
done

# --- summary ---------------------------------------------------------------------------------------
kill_root_processes
pass=1
summary=()
for i in "${!commands[@]}"; do
  word=ok; [ "${statuses[i]}" -eq 0 ] || { word=FAILED; pass=0; }
  summary+=("command $((i + 1)): exit ${statuses[i]} ($word)  ${commands[i]}")
done
# Any PNG a command names with --out must exist, be non-empty and be a PNG.
for c in "${commands[@]}"; do
  for png in $(grep -oE -- '--out[ =][^ ]+\.png' <<<"$c" | sed -E 's/^--out[ =]//'); do
    f="$clone/$png"
    if [ -s "$f" ] && [ "$(head -c 8 "$f" | od -An -tx1 | tr -d ' \n')" = 89504e470d0a1a0a ]; then
      summary+=("$png: PNG of $(stat -c %s "$f") bytes")
    else
      summary+=("$png: MISSING, empty or not a PNG"); pass=0
    fi
  done
done
ctest_line="$(grep -aE '^[0-9]+% tests passed, [0-9]+ tests? failed out of [0-9]+' "$log" | tail -n1)"
ctest_time="$(grep -aE '^Total Test time' "$log" | tail -n1)"
# ctest's list of the tests that did not run (skipped: e.g. the Sponza tests, no assets here)
ctest_not_run="$(awk '/^The following tests did not run:/ { n = ""; inside = 1; next }
                      inside && /^\t/ { sub(/^\t[ ]*/, ""); n = n (n == "" ? "" : "; ") $0; next }
                      { inside = 0 } END { print n }' "$log")"

echo
echo "==================================================================================="
echo " vct fresh Debian 12 (minbase) check: $( ((pass)) && echo PASS || echo FAIL)"
echo "   $(date -u '+%Y-%m-%d %H:%M UTC'), commit $(git -C "$clone" rev-parse --short HEAD 2>/dev/null), $(( ($(date +%s) - started) / 60 )) min in all"
for s in "${summary[@]}"; do echo "   $s"; done
[ -n "$ctest_line" ] && echo "   ctest: $ctest_line"
[ -n "$ctest_time" ] && echo "   ctest: $ctest_time"
[ -n "$ctest_line" ] && echo "   ctest: did not run: ${ctest_not_run:-none}"
((pass)) || echo "   first error in the log: $(grep -anm1 -E 'ninja: error|CMake Error|^E: |FAILED:|[Ee]rror:|\*\*\*Failed' "$log" | cut -c1-160)"
echo "   root: $(du -sh --one-file-system "$root_dir" 2>/dev/null | cut -f1) in $root_dir"
echo "   log: $log"
echo "==================================================================================="

cleanup
if ((pass)) && [ "${VCT_FRESH_KEEP_ROOT:-0}" != 1 ]; then
  rm -rf --one-file-system "$root_dir"
  echo "root removed (VCT_FRESH_KEEP_ROOT=1 keeps it)"
else
  echo "root kept for inspection: $root_dir (chroot into it; a new run of this script replaces it)"
fi
((pass)) && exit 0 || exit 1
