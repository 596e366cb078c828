#!/usr/bin/env bash
# Builds PARPE's installable image for the operating system it runs on, with jpackage (JDK 17),
# into target/dist/. The image has its own Java runtime: no JDK or Maven is needed to run it.
#   Linux:   target/dist/parpe-ide/ (app image), parpe-VERSION-linux-ARCH.tar.gz and a .deb
#            (desktop entry, icon, .parsl/.xml file associations)
#   Windows: target/dist/parpe-ide/ and an .msi (run from Git Bash; needs the WiX toolset 3)
#   macOS:   target/dist/parpe-ide.app and a .dmg
# The image holds two programs: parpe-ide (the IDE) and parpe (the command line), plus the
# examples, the documentation and the PARSL specification.
#   --smoke   then check every example and run one in the simulator with the image alone
#   --no-installer   only the app image and the archive (no .deb/.msi/.dmg)
set -euo pipefail
root=$(cd "$(dirname "$(readlink -f "${BASH_SOURCE[0]}")")/.." && pwd)
cd "$root"
smoke=0
installer=1
for a in "$@"; do
    case "$a" in
        --smoke) smoke=1 ;;
        --no-installer) installer=0 ;;
        *) echo "dist.sh: unknown option '$a' (expected --smoke or --no-installer)" >&2; exit 2 ;;
    esac
done
version=$(sed -n 's|^  <version>\([0-9.]*\).*</version>|\1|p' pom.xml | head -n 1)
case "$(uname -s)" in
    Linux) os=linux ;;
    Darwin) os=macos ;;
    MINGW*|MSYS*|CYGWIN*) os=windows ;;
    *) echo "dist.sh: unsupported system $(uname -s)" >&2; exit 2 ;;
esac
arch=$(uname -m)

cli_jar=parpe-cli/target/parpe.jar
gui_jar=parpe-gui/target/parpe-gui.jar
if [ ! -f "$cli_jar" ] || [ ! -f "$gui_jar" ]; then
    echo "dist.sh: building the jars" >&2
    mvn -q -B -DskipTests -Dexec.skip=true package
fi

out=$root/target/dist
input=$out/input
rm -rf "$out"
mkdir -p "$input"
cp "$cli_jar" "$gui_jar" "$input/"
cp -r examples docs "$input/"
[ -d spec ] && cp -r spec "$input/"
cp README.md "$input/"

common=(--name parpe-ide --app-version "$version" --vendor "PARPE"
        --description "PolyKinetic Phase Automata Robot Programming Environment")
icon=packaging/parpe.png
echo "dist.sh: app image for $os $arch" >&2
jpackage --type app-image "${common[@]}" --dest "$out" --input "$input" --main-jar parpe-gui.jar \
    --java-options '-Dparpe.examples=$APPDIR/examples' \
    --add-launcher parpe=packaging/parpe-cli.properties \
    --jlink-options '--strip-debug --no-man-pages --no-header-files' \
    $( [ "$os" = linux ] && echo --icon "$icon" )

case "$os" in
    linux)
        image=$out/parpe-ide
        tar -czf "$out/parpe-$version-linux-$arch.tar.gz" -C "$out" parpe-ide
        if [ "$installer" = 1 ]; then
            jpackage --type deb "${common[@]}" --dest "$out" --app-image "$image" \
                --linux-shortcut --linux-menu-group Education --linux-app-category education \
                --icon "$icon" --file-associations packaging/parsl-files.properties \
                --file-associations packaging/xml-files.properties
        fi
        cli=$image/bin/parpe ;;
    windows)
        image=$out/parpe-ide
        [ "$installer" = 1 ] && jpackage --type msi "${common[@]}" --dest "$out" --app-image "$image" \
            --win-menu --win-shortcut --win-dir-chooser --file-associations packaging/parsl-files.properties
        cli=$image/parpe.exe ;;
    macos)
        image=$out/parpe-ide.app
        [ "$installer" = 1 ] && jpackage --type dmg "${common[@]}" --dest "$out" --app-image "$image" \
            --file-associations packaging/parsl-files.properties
        cli=$image/Contents/MacOS/parpe ;;
esac
ls -l "$out" | sed -n '2,$p' >&2

if [ "$smoke" = 1 ]; then
    # The image alone: no Java, no Maven on PATH, no JAVA_HOME.
    examples=$(find "$image" -type d -name examples | head -n 1)
    work=$(mktemp -d)
    cp -r "$examples"/. "$work/"
    run() { (cd "$work" && env -i HOME="$work" PATH=/nonexistent "$cli" "$@"); }
    echo "dist.sh: smoke test of $cli" >&2
    scripts=()
    for f in "$work"/*.xml; do scripts+=("$(basename "$f")"); done
    run check "${scripts[@]}"
    run run hello-snake.xml --sim snake --duration 2 --trace trace.csv --metrics -
    rows=$(wc -l < "$work/trace.csv")
    [ "$rows" = 202 ] || { echo "dist.sh: smoke test: trace has $rows lines, expected 202" >&2; exit 1; }
    rm -rf "$work"
    echo "dist.sh: smoke test passed" >&2
fi
