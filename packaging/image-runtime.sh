#!/usr/bin/env bash
# Builds a Java runtime holding only the modules of PARPE's installable image into DIR/runtime
# (runtime-modules.sh over the two programs' jars, as dist.sh builds the image's own) and prints
# its java. test-all runs the IDE's tests on it, so that a feature needing a module the image
# leaves out fails there, not on a student's machine.
#   image-runtime.sh DIR
set -euo pipefail
root=$(cd "$(dirname "$(readlink -f "${BASH_SOURCE[0]}")")/.." && pwd)
out=$(cd "$1" && pwd)
cd "$root"
# Maven's output goes to standard error: standard output is the one line naming the java
mvn -q -B -Dstyle.color=never -DskipTests -Dexec.skip=true -pl parpe-cli,parpe-gui -am package >&2
mkdir -p "$out/jars"
cp parpe-cli/target/parpe.jar parpe-gui/target/parpe-gui.jar "$out/jars/"
modules=$(packaging/runtime-modules.sh "$out/jars")
echo "image-runtime.sh: the image's modules: $modules" >&2
rm -rf "$out/runtime"
jlink --add-modules "$modules" --no-man-pages --no-header-files --output "$out/runtime"
echo "$out/runtime/bin/java"
