#!/usr/bin/env bash
# Builds parpe_VERSION_ARCH.deb from the jpackage app image (called by packaging/dist.sh):
#   deb.sh IMAGE VERSION OUTDIR
# Written here rather than with `jpackage --type deb`, whose package runs xdg-desktop-menu and
# xdg-mime in its maintainer scripts: they fail where there is no menu tree, pull xdg-utils with
# dozens of packages, and make the program the default for every type it names. This package
# has no maintainer scripts at all. Its files:
#   /usr/lib/parpe/                    the app image (own Java runtime, examples, docs)
#   /usr/bin/parpe, /usr/bin/parpe-ide links to the two launchers
#   /usr/share/applications/parpe.desktop        the one menu entry (Education)
#   /usr/share/mime/packages/parpe.xml           .parsl = application/x-parsl+xml (not .xml)
#   /usr/share/icons/hicolor/256x256/apps/parpe.png
# The menu, MIME and icon caches are refreshed by the triggers that desktop-file-utils,
# shared-mime-info and the icon theme declare on these folders, where those are installed; dpkg
# removes every file on purge and the same triggers forget them. Not /opt/parpe: no Debian
# package owns /opt (base-files only makes it), so the package that put /opt/parpe there became
# /opt's owner, and its purge removed /opt or, with other programs in it, warned "directory
# '/opt' not empty so not removed". /usr/lib is owned by base-files, and Debian Policy 9.1.1 lets
# a package keep a mixture of architecture-dependent and -independent files in /usr/lib/NAME.
set -euo pipefail
image=$1 version=$2 out=$3
here=$(cd "$(dirname "$(readlink -f "${BASH_SOURCE[0]}")")" && pwd)
arch=$(dpkg --print-architecture)
pkg=$out/deb/parpe
rm -rf "$out/deb"
mkdir -p "$pkg/DEBIAN" "$pkg/usr/lib" "$pkg/usr/bin" "$pkg/usr/share/applications" \
    "$pkg/usr/share/mime/packages" "$pkg/usr/share/icons/hicolor/256x256/apps"
cp -a "$image" "$pkg/usr/lib/parpe"
ln -s ../lib/parpe/bin/parpe "$pkg/usr/bin/parpe"
ln -s ../lib/parpe/bin/parpe-ide "$pkg/usr/bin/parpe-ide"
install -m 644 "$here/parpe.desktop" "$pkg/usr/share/applications/parpe.desktop"
install -m 644 "$here/parpe-mime.xml" "$pkg/usr/share/mime/packages/parpe.xml"
install -m 644 "$here/../../parpe-gui/src/main/resources/org/parpe/gui/parpe.png" "$pkg/usr/share/icons/hicolor/256x256/apps/parpe.png"

# Depends: the packages of the shared libraries the runtime's native code links to, and GTK 3
# for SWT (which loads it at run time, so ldd cannot see it). No versions: Ubuntu 24.04's
# renamed t64 libraries provide these names. Left out: the natives of what PARPE never uses
# (the splash screen, javax.sound, JPEG images), which would add libjpeg62-turbo, libgif7,
# libpng16-16 and libasound2 (Debian's names; Ubuntu's JPEG library has another).
libs=$(find "$pkg/usr/lib/parpe" -type f \( -name '*.so' -o -path '*/bin/*' \) \
        ! -name libsplashscreen.so ! -name libjsound.so ! -name libjavajpeg.so -exec ldd {} + 2>/dev/null \
    | sed -n 's|.*=> \(/[^ ]*\) .*|\1|p' | grep -v "^$pkg/" | sort -u)
# One dpkg -S for all (it reads every package's file list); with the merged /usr, a library is
# owned under /lib or /usr/lib, so both spellings are asked.
owners=$(for l in $libs; do r=$(readlink -f "$l"); echo "$l"; echo "$r"; echo "${r#/usr}"; done | sort -u \
    | { xargs dpkg -S 2>/dev/null || true; } | cut -d: -f1 | sed 's/, /\n/g' | sort -u)
depends=$( { echo libgtk-3-0; echo "$owners"; } | sort -u | paste -sd, | sed 's/,/, /g')
size=$(du -sk "$pkg" | cut -f1)
sed -e "s/@VERSION@/$version/" -e "s/@ARCH@/$arch/" -e "s/@SIZE@/$size/" -e "s/@DEPENDS@/$depends/" \
    "$here/control" > "$pkg/DEBIAN/control"
echo "deb.sh: Depends: $depends" >&2
dpkg-deb --root-owner-group -Zxz --build "$pkg" "$out/parpe_${version}_${arch}.deb" >/dev/null
rm -rf "$out/deb"
