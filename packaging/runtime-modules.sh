#!/usr/bin/env bash
# Prints the Java modules of PARPE's image runtime, comma-separated: those jdeps finds that the
# jars in DIR use. dist.sh builds the image's runtime from them; image-runtime.sh builds one for the
# IDE's tests, a runtime of exactly these modules, since jdeps sees only static references and a
# module a class reaches lazily (a service, a locale, a charset) would be missing only there.
# Relative names, and the system's class-path separator, so that Windows' jdeps understands them.
#   runtime-modules.sh DIR
set -euo pipefail
cd "$1"
sep=:
case "$(uname -s)" in MINGW*|MSYS*|CYGWIN*) sep=';' ;; esac
modules=$(jdeps --print-module-deps --ignore-missing-deps --multi-release 17 \
    --class-path "$(ls ./*.jar | paste -sd "$sep")" ./*.jar 2>/dev/null | tail -n 1)
case "$modules" in java.base*) ;; *) echo "runtime-modules.sh: jdeps found no modules ('$modules')" >&2; exit 1 ;; esac
# jdk.localedata: the number formats of the user's locale (in a German sweep dialog "2,5" is 2.5,
# not 2 and 5); java.base finds it as a service, which jdeps does not see (SweepDialogGuiTest).
echo "$modules,jdk.localedata"
