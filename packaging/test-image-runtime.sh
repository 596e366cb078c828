#!/usr/bin/env bash
# Runs PARPE's IDE tests (under xvfb-run) on a Java runtime holding only the modules of the
# installable image (image-runtime.sh), on their own; test-all runs them so inside its one
# `mvn verify`. The class path is Maven's runtime one, the jars dist.sh copies into the image
# (the IDE's exclusions in parpe-gui/pom.xml apply to both). Extra arguments go to Maven.
set -euo pipefail
root=$(cd "$(dirname "$(readlink -f "${BASH_SOURCE[0]}")")/.." && pwd)
cd "$root"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
java=$(packaging/image-runtime.sh "$work")
mvn -B verify -pl parpe-gui -am -Dparpe.gui.test.jvm="$java" -Dtest='org/parpe/gui/**/*' \
    -Dsurefire.failIfNoSpecifiedTests=false "$@"
