#!/usr/bin/env bash
# Installs PARPE's .deb into a fresh Debian 12 root, as a teacher would, and checks it there
# (packaging/linux/deb-test-inside.sh): the install with only the declared dependencies and no
# desktop-menu tree, parpe and parpe-ide on PATH, `parpe check` on every installed example and
# lesson, a 2 s simulated run, the IDE on a lesson under an X server with a screenshot
# (target/deb-test/ide.png), the IDE in German and Japanese by LANG (target/deb-test/ide-de.png,
# ide-ja.png: its own menus must be in that language), the first-use copy of the examples and
# lesson 11's optimize there, the one menu entry and the .parsl-only file type, then a purge that leaves nothing behind.
# Needs root (or unprivileged user namespaces), mmdebstrap, Xvfb and Debian's mirror
# (PARPE_DEBIAN_MIRROR, default http://deb.debian.org/debian). Builds the .deb with
# packaging/dist.sh when target/dist has none. Everything it makes is under target/deb-test.
set -euo pipefail
root=$(cd "$(dirname "$(readlink -f "${BASH_SOURCE[0]}")")/.." && pwd)
cd "$root"
started=$(date +%s)
mirror=${PARPE_DEBIAN_MIRROR:-http://deb.debian.org/debian}
deb=$(ls target/dist/parpe_*.deb 2>/dev/null | head -n 1 || true)
if [ -z "$deb" ]; then
    packaging/dist.sh
    deb=$(ls target/dist/parpe_*.deb | head -n 1)
fi
out=$root/target/deb-test
rm -rf "$out"
mkdir -p "$out"

# An X server outside the root; the root reaches it through the abstract socket (same network).
n=90
while [ -e "/tmp/.X$n-lock" ] || [ -e "/tmp/.X11-unix/X$n" ]; do n=$((n + 1)); done
Xvfb ":$n" -screen 0 1400x900x24 -nolisten tcp -ac > "$out/xvfb.log" 2>&1 &
xvfb=$!
trap 'kill "$xvfb" 2>/dev/null || true' EXIT
for _ in $(seq 50); do [ -e "/tmp/.X11-unix/X$n" ] && break; sleep 0.1; done

echo "test-deb-install: $(basename "$deb") into a fresh Debian 12 root from $mirror" >&2
TMPDIR=$out mmdebstrap --variant=apt --quiet \
    --customize-hook="upload '$deb' /tmp/parpe.deb" \
    --customize-hook="upload '$root/packaging/linux/deb-test-inside.sh' /tmp/inside.sh" \
    --customize-hook="chroot \"\$1\" env DISPLAY=:$n sh /tmp/inside.sh > '$out/inside.log' 2>&1; echo \$? > '$out/inside.rc'; touch \"\$1/tmp/ide.png\" \"\$1/tmp/ide-de.png\" \"\$1/tmp/ide-ja.png\"" \
    --customize-hook="download /tmp/ide.png '$out/ide.png'" \
    --customize-hook="download /tmp/ide-de.png '$out/ide-de.png'" \
    --customize-hook="download /tmp/ide-ja.png '$out/ide-ja.png'" \
    bookworm "$out/root" "deb $mirror bookworm main" < /dev/null
rm -rf "$out/root"
grep -E '^(ok|FAIL|the \.deb|the IDE in)' "$out/inside.log" >&2
if [ "$(cat "$out/inside.rc")" != 0 ]; then
    echo "test-deb-install: FAILED (the whole log: $out/inside.log)" >&2
    exit 1
fi
echo "test-deb-install: passed in $(( $(date +%s) - started )) s; the IDE's window: $out/ide.png (German:" \
    "$out/ide-de.png, Japanese: $out/ide-ja.png)" >&2
