#!/usr/bin/env bash
# Runs PARPE's IDE tests (under xvfb-run) on a Java runtime holding only
# the modules of the installable image (runtime-modules.sh over the two programs' jars), so that
# a feature needing a module the image leaves out fails here, not on a student's machine. The
# class path is Maven's runtime one, the jars dist.sh copies into the image (the IDE's
# exclusions in parpe-gui/pom.xml apply to both). Extra arguments go to Maven.
set -euo pipefail
root=$(cd "$(dirname "$(readlink -f "${BASH_SOURCE[0]}")")/.." && pwd)
cd "$root"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mvn -q -B -DskipTests -Dexec.skip=true -pl parpe-cli,parpe-gui -am package
cp parpe-cli/target/parpe.jar parpe-gui/target/parpe-gui.jar "$work/"
modules=$(packaging/runtime-modules.sh "$work")
echo "test-image-runtime.sh: the image's modules: $modules" >&2
jlink --add-modules "$modules" --no-man-pages --no-header-files --output "$work/runtime"
# The IDE's tests: they exercise what a student touches (the CLI's and the core's run on the full JDK in the
# main verify, and run the same code the IDE calls); the whole suite a second time would double CI's time.
# The layouts in every language (tag "screens", 126 screens, about 2.5 min) are checked once, in the main verify:
# they test widths of texts, which do not depend on the Java runtime.
mvn -B verify -pl parpe-gui -am -Djvm="$work/runtime/bin/java" -Dtest='org/parpe/gui/**/*' \
    -DexcludedGroups=screens -Dsurefire.failIfNoSpecifiedTests=false "$@"
