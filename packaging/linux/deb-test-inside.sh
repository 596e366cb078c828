#!/bin/sh
# Run by packaging/test-deb-install.sh inside a fresh Debian root (as root, DISPLAY set to an
# X server outside): installs /tmp/parpe.deb as a teacher would and checks what issue 22 asked.
# Every failed check prints "FAIL: …" and the script exits non-zero at the end.
set -u
failed=0
fail() { echo "FAIL: $*"; failed=1; }
ok() { echo "ok: $*"; }
export DEBIAN_FRONTEND=noninteractive LC_ALL=C.UTF-8
examples=/usr/lib/parpe/lib/app/examples

# A student who is not root, so that read-only installed files stay read-only.
echo 'student:x:1000:1000::/home/student:/bin/sh' >> /etc/passwd
echo 'student:x:1000:' >> /etc/group
mkdir -p /home/student && chown 1000:1000 /home/student
as_student() { setpriv --reuid=1000 --regid=1000 --clear-groups env HOME=/home/student USER=student \
    PATH=/usr/local/bin:/usr/bin:/bin DISPLAY="$DISPLAY" "$@"; }

# 1. The install: no desktop-menu tree, no xdg-utils, only the declared dependencies.
[ -d /usr/share/desktop-directories ] && fail "the fresh root already has a desktop-menu tree"
dpkg-query -W -f='${Package}\n' | sort > /tmp/before
apt-get install -y -q --no-install-recommends /tmp/parpe.deb > /tmp/apt.log 2>&1 || { cat /tmp/apt.log; fail "apt-get install"; }
dpkg-query -W -f='${Package}\n' | sort > /tmp/after
new=$(comm -13 /tmp/before /tmp/after)
echo "the .deb brought $(echo "$new" | wc -l) packages (with parpe itself)"
for p in xdg-utils perl zutty x11-xserver-utils; do
    echo "$new" | grep -qx "$p" && fail "installing PARPE pulled $p"
done
status=$(dpkg-query -W -f='${Status}' parpe 2>&1)
[ "$status" = "install ok installed" ] && ok "dpkg status: $status" || fail "dpkg status of parpe: $status"
apt-get check -q > /dev/null 2>&1 && ok "apt-get check" || fail "apt-get check after the install"

# 2. The commands on PATH.
[ "$(command -v parpe)" = /usr/bin/parpe ] && ok "parpe on PATH" || fail "parpe is not /usr/bin/parpe"
[ "$(command -v parpe-ide)" = /usr/bin/parpe-ide ] && ok "parpe-ide on PATH" || fail "parpe-ide is not /usr/bin/parpe-ide"
as_student parpe --version || fail "parpe --version"

# Size and memory: a trimmed runtime and each library once (179 MB before); a bounded heap.
size=$(du -sm /usr/lib/parpe | cut -f1)
[ "$size" -le 100 ] && ok "installed size $size MB" || fail "installed size $size MB, more than 100 MB"
# heap: the JVM's own figure, printed by the installed launcher's JVM
heap() { as_student env JAVA_TOOL_OPTIONS="$1 -XX:+PrintFlagsFinal" parpe --version 2>/dev/null | awk '$2 == "MaxHeapSize" {print $4}'; }
h=$(heap "")
[ -n "$h" ] && [ "$h" -le $((768 * 1024 * 1024)) ] && ok "parpe's heap is bounded: $((h / 1024 / 1024)) MB" \
    || fail "parpe's heap is not bounded to 768 MB (MaxHeapSize '$h')"
# the override docs/install.md and docs/cluster.md give must win over the launcher's bound
h=$(heap "-Xmx1g")
[ "$h" = $((1024 * 1024 * 1024)) ] && ok "JAVA_TOOL_OPTIONS=-Xmx1g gives a 1024 MB heap" \
    || fail "JAVA_TOOL_OPTIONS=-Xmx1g is overridden by the launcher (MaxHeapSize '$h')"

# 3. Every installed example and lesson checks, from PATH.
as_student sh -c "cd /tmp && parpe check $examples/*.xml $examples/tutorial/*.xml" > /tmp/check.log 2>&1 \
    && ok "parpe check: $(grep -c ': ok$' /tmp/check.log) scripts" || { cat /tmp/check.log; fail "parpe check on the installed examples"; }

# 4. A 2 s simulated run.
as_student sh -c "cd /tmp && parpe run $examples/hello-snake.xml --sim snake --duration 2 --trace /tmp/trace.csv --metrics -" \
    || fail "parpe run"
rows=$(wc -l < /tmp/trace.csv 2>/dev/null || echo 0)
[ "$rows" = 202 ] && ok "2 s run: 202 trace lines" || fail "2 s run: trace has $rows lines, expected 202"

# 5. The IDE from the menu's command, on a lesson, with a picture of its window; its first use
#    copies the examples to the student's own folder.
as_student timeout 180 parpe-ide $examples/tutorial/03-hello-snake.xml --run-for 2 --screenshot /tmp/ide.png --exit \
    > /tmp/ide.log 2>&1 || { cat /tmp/ide.log; fail "parpe-ide with a screenshot"; }
[ -s /tmp/ide.png ] && ok "IDE screenshot /tmp/ide.png" || fail "no IDE screenshot"
[ -f /home/student/PARPE/examples/tutorial/10-race-snake.xml ] && ok "examples copied to ~/PARPE/examples" \
    || fail "the IDE did not copy the examples to ~/PARPE/examples"
# `parpe lesson.xml` opens the IDE on the file (and --exit closes it again).
as_student sh -c "cd /home/student/PARPE/examples/tutorial && timeout 180 parpe 04-waves-snake.xml --exit" \
    > /tmp/open.log 2>&1 && ok "parpe FILE.xml opens the IDE" || { cat /tmp/open.log; fail "parpe FILE.xml"; }
# Lesson 11 in the student's folder: optimize writes its result beside the script.
as_student sh -c "cd /home/student/PARPE && parpe optimize examples/tutorial/10-race-snake.xml --sim snake:n=8 --duration 1 --budget 8 --seed 1" \
    > /tmp/opt.log 2>&1 || { cat /tmp/opt.log; fail "lesson 11's optimize in ~/PARPE"; }
[ -f /home/student/PARPE/examples/tutorial/10-race-snake-optimised.xml ] && ok "lesson 11's optimize wrote its script" \
    || fail "lesson 11's optimize wrote no script"

# 5b. The IDE in the student's language (issue 38): with LANG=de_DE.UTF-8 and ja_JP.UTF-8 (the
#     locales generated, and fonts-noto-cjk, which the .deb recommends, for the Japanese glyphs)
#     it opens with its own menus in German and Japanese: their texts, written by the automated
#     launch (-Dparpe.menus, Automation.MENUS), and a picture of each window.
languages_from=$(date +%s)
apt-get install -y -q --no-install-recommends locales fonts-noto-cjk > /tmp/apt-lang.log 2>&1 \
    || { cat /tmp/apt-lang.log; fail "installing locales and fonts-noto-cjk"; }
sed -i -E 's/^# *(de_DE\.UTF-8 UTF-8|ja_JP\.UTF-8 UTF-8)$/\1/' /etc/locale.gen
locale-gen > /tmp/locale-gen.log 2>&1 || { cat /tmp/locale-gen.log; fail "locale-gen"; }
for lang in de_DE.UTF-8:Datei ja_JP.UTF-8:ファイル; do
    locale=${lang%%:*}; file_menu=${lang#*:}; code=${locale%%_*}
    as_student env -u LC_ALL LANG="$locale" JAVA_TOOL_OPTIONS="-Dparpe.menus=/tmp/menus-$code.txt" timeout 180 \
        parpe-ide $examples/tutorial/03-hello-snake.xml --screenshot /tmp/ide-$code.png --exit > /tmp/ide-$code.log 2>&1 \
        || { cat /tmp/ide-$code.log; fail "parpe-ide with LANG=$locale"; }
    first=$(head -n 1 /tmp/menus-$code.txt 2>/dev/null)
    case "$first" in
        "$file_menu"*) ok "with LANG=$locale the IDE's File menu reads '$first' (/tmp/ide-$code.png)" ;;
        *) fail "with LANG=$locale the IDE's File menu reads '$first', expected '$file_menu' (menus: $(tr '\n' ' ' < /tmp/menus-$code.txt 2>/dev/null))" ;;
    esac
done
echo "the IDE in German and Japanese took $(( $(date +%s) - languages_from )) s (with installing locales and fonts-noto-cjk)"

# 6. The menu entry and the file types: one entry, .parsl only, never a default for XML.
desktops=$(dpkg -L parpe | grep '^/usr/share/applications/.*\.desktop$')
[ "$(echo "$desktops" | wc -l)" = 1 ] && ok "one menu entry: $desktops" || fail "menu entries: $desktops"
d=/usr/share/applications/parpe.desktop
grep -qx 'Name=PARPE' $d && grep -q '^Categories=Education;' $d && grep -qx 'Icon=parpe' $d \
    && grep -qx 'MimeType=application/x-parsl+xml;' $d && ok "menu entry PARPE, Education, icon, .parsl" || fail "menu entry: $(cat $d)"
[ -f /usr/share/icons/hicolor/256x256/apps/parpe.png ] || fail "no icon in the hicolor theme"
grep -q 'pattern="\*\.xml"' /usr/share/mime/packages/parpe.xml && fail "the MIME file claims *.xml"
found=$(grep -rl parpe /usr/share/applications /etc/xdg /root/.config 2>/dev/null | grep -v '/parpe.desktop$')
[ -z "$found" ] && ok "no defaults.list/mimeapps.list names PARPE" || fail "PARPE named in $found"

# A desktop's cache builders (installed after PARPE, as on a PC that gets a desktop later).
apt-get install -y -q --no-install-recommends desktop-file-utils shared-mime-info > /tmp/apt2.log 2>&1 \
    || { cat /tmp/apt2.log; fail "installing desktop-file-utils shared-mime-info"; }
desktop-file-validate $d && ok "desktop-file-validate" || fail "desktop-file-validate $d"
grep -qx 'application/x-parsl+xml=parpe.desktop;' /usr/share/applications/mimeinfo.cache \
    && ok ".parsl opens in PARPE" || fail ".parsl not in mimeinfo.cache: $(grep parsl /usr/share/applications/mimeinfo.cache)"
grep '^application/xml=' /usr/share/applications/mimeinfo.cache | grep -q parpe && fail "PARPE offered for application/xml"
grep -q ':application/x-parsl+xml:\*\.parsl$' /usr/share/mime/globs2 && ok "*.parsl is application/x-parsl+xml" \
    || fail "*.parsl not in globs2"
grep ':\*\.xml$' /usr/share/mime/globs2 | grep -q parsl && fail "*.xml maps to PARSL"
# The triggers of those packages see PARPE's files when it is installed again.
apt-get install -y -q --reinstall --no-install-recommends /tmp/parpe.deb > /tmp/apt3.log 2>&1 || { cat /tmp/apt3.log; fail "reinstall"; }

# 7. Purge: nothing of PARPE left, nothing else touched, and no warning. Another program in /opt,
#    as on many PCs: a package that owned /opt warned "directory '/opt' not empty so not removed"
#    (and removed an empty /opt, which base-files makes) (issue 31 item 3.6).
owners=$(dpkg -S /opt 2>/dev/null)
[ -z "$owners" ] && ok "no package owns /opt" || fail "packages own /opt: $owners"
mkdir -p /opt/other-program && echo kept > /opt/other-program/file
apt-get purge -y -q parpe > /tmp/purge.log 2>&1 || { cat /tmp/purge.log; fail "apt-get purge"; }
grep -qi 'warning' /tmp/purge.log && fail "apt-get purge warned: $(grep -i warning /tmp/purge.log)" \
    || ok "apt-get purge without a warning"
[ "$(cat /opt/other-program/file 2>/dev/null)" = kept ] && ok "another program in /opt is kept" \
    || fail "the purge touched /opt/other-program"
rm -r /opt/other-program
[ -d /opt ] && ok "/opt is kept" || fail "the purge removed /opt"
[ -z "$(dpkg-query -W -f='${Status}' parpe 2>/dev/null)" ] && ok "dpkg forgot parpe" \
    || fail "dpkg still knows parpe: $(dpkg-query -W -f='${Status}' parpe)"
left=$(find / -xdev \( -path /proc -o -path /sys -o -path /dev -o -path /home -o -path /tmp \) -prune -o -iname '*parpe*' -print)
[ -z "$left" ] && ok "no file named parpe left" || fail "left after purge: $left"
left=$(grep -rlE 'parsl|parpe' /usr/share/mime /usr/share/applications /etc 2>/dev/null)
[ -z "$left" ] && ok "no MIME or menu cache names PARPE" || fail "left after purge in: $left"

exit $failed
