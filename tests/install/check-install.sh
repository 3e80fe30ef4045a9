#!/usr/bin/env bash
# check-install.sh BUILD_DIR SOURCE_DIR: installs the built tree into a scratch prefix and checks it,
# then builds the Debian package and checks that too. Fails with a message naming what is missing.
set -euo pipefail
build=$1
source=$2
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
fail() { echo "check-install: $*" >&2; exit 1; }

prefix=$scratch/usr
cmake --install "$build" --prefix "$prefix" >/dev/null

# What the install tree must hold.
app_id=io.github.cuelab.CueLab
expected=(
  bin/cuelab bin/cuelab-cli
  share/applications/$app_id.desktop
  share/metainfo/$app_id.metainfo.xml
)
for size in 16 24 32 48 64 128 256; do expected+=(share/icons/hicolor/${size}x${size}/apps/$app_id.png); done
for f in "$source"/resources/examples/*.json; do expected+=(share/cuelab/examples/$(basename "$f")); done
for f in "${expected[@]}"; do [ -e "$prefix/$f" ] || fail "the install tree lacks $f"; done
[ -x "$prefix/bin/cuelab" ] && [ -x "$prefix/bin/cuelab-cli" ] || fail "the programs are not executable"
echo "check-install: ${#expected[@]} expected files installed"

# Each icon is the size its folder says.
for size in 16 24 32 48 64 128 256; do
  png=$prefix/share/icons/hicolor/${size}x${size}/apps/$app_id.png
  dims=$(od -An -tu1 -j16 -N8 "$png" | awk '{print $3*256+$4 "x" $7*256+$8}')
  [ "$dims" = "${size}x${size}" ] || fail "$png is $dims, not ${size}x${size}"
done

desktop-file-validate "$prefix/share/applications/$app_id.desktop" || fail "the desktop entry does not validate"
appstreamcli validate --no-net --pedantic "$prefix/share/metainfo/$app_id.metainfo.xml" >/dev/null ||
  fail "the metainfo does not validate: $(appstreamcli validate --no-net "$prefix/share/metainfo/$app_id.metainfo.xml")"
grep -q "^Exec=cuelab" "$prefix/share/applications/$app_id.desktop" || fail "the desktop entry does not start cuelab"

# The installed programs run from the install tree, on the installed examples.
"$prefix/bin/cuelab-cli" --version | grep -q "^cuelab-cli " || fail "the installed cuelab-cli does not run"
"$prefix/bin/cuelab-cli" validate "$prefix/share/cuelab/examples/half-ball-cut.json" || fail "an installed example does not validate"
"$prefix/bin/cuelab" --screenshot "$scratch/shot.png" "$prefix/share/cuelab/examples/half-ball-cut.json" --size 320x200 ||
  fail "the installed cuelab cannot render an installed example"
[ -s "$scratch/shot.png" ] || fail "the installed cuelab wrote no picture"

# The Debian package: built by CPack from the same tree, with library dependencies from
# dpkg-shlibdeps; it unpacks into the same files and its programs run from there.
(cd "$scratch" && cpack -G DEB --config "$build/CPackConfig.cmake" -B "$scratch/pkg" >/dev/null) || fail "cpack -G DEB failed"
deb=$(ls "$scratch"/pkg/*.deb 2>/dev/null | head -1)
[ -n "$deb" ] || fail "cpack made no .deb"
info=$(dpkg-deb --info "$deb")
echo "$info" | grep -q "^ Package: cuelab$" || fail "the package is not named cuelab"
echo "$info" | grep -q "^ Depends:.*libqt6widgets6" || fail "the package does not depend on Qt Widgets: $(echo "$info" | grep Depends)"
contents=$(dpkg-deb --contents "$deb")
for f in usr/bin/cuelab usr/bin/cuelab-cli usr/share/applications/$app_id.desktop usr/share/cuelab/examples/half-ball-cut.json; do
  echo "$contents" | grep -q "\./$f\$" || fail "the package lacks /$f"
done
dpkg-deb -x "$deb" "$scratch/unpacked"
"$scratch/unpacked/usr/bin/cuelab-cli" simulate "$scratch/unpacked/usr/share/cuelab/examples/straight-shot.json" >/dev/null ||
  fail "cuelab-cli from the package does not simulate"
echo "check-install: $(basename "$deb") ($(du -k "$deb" | cut -f1) KiB) builds, unpacks and runs"
