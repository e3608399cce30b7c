#!/usr/bin/env bash
# Builds the .deb with CPack, unpacks it into a temporary root and runs the packaged
# spira-cli from there. Usage: check_deb.sh BUILD_DIR WITH_GUI(ON|OFF)
set -euo pipefail
build=$1
with_gui=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cpack -G DEB --config "$build/CPackConfig.cmake" -B "$work/pkg" >"$work/cpack.log" 2>&1 || { cat "$work/cpack.log"; exit 1; }
deb=$(ls "$work"/pkg/*.deb | head -1)
[ -f "$deb" ] || { echo "no .deb produced"; exit 1; }
info=$(dpkg-deb -I "$deb")  # captured first: grep -q closing the pipe early would fail it under pipefail
grep -q "Package: spira" <<<"$info" || { echo "package metadata lacks 'Package: spira'"; exit 1; }
dpkg-deb -x "$deb" "$work/root"
need=(usr/bin/spira-cli usr/bin/spira-import usr/share/applications/spira.desktop usr/share/icons/hicolor/scalable/apps/spira.svg
      usr/share/spira/samples/dome.stl usr/share/spira/samples/open_cylinder.stl usr/share/metainfo/org.spira.Spira.metainfo.xml)
[ "$with_gui" = "ON" ] && need+=(usr/bin/spira)
for f in "${need[@]}"; do
  [ -e "$work/root/$f" ] || { echo "package lacks $f"; exit 1; }
done
version=$("$work/root/usr/bin/spira-cli" --version)
echo "$version"
[[ "$version" == "spira-cli "* ]] || { echo "unexpected version output: $version"; exit 1; }
"$work/root/usr/bin/spira-cli" info "$work/root/usr/share/spira/samples/dome.stl" >/dev/null
# STEP is read by the packaged spira-import next to the packaged spira-cli.
"$work/root/usr/bin/spira-cli" info "$(dirname "$0")/../data/hostile/step/unresolved_point.step" >/dev/null
# The Python module, when the build made one, imports from the package and plans.
if compgen -G "$build/python/spira*.so" >/dev/null; then
  PYTHONPATH="$work/root/usr/lib/python3/dist-packages" /usr/bin/python3 -c \
    "import spira; assert len(spira.plan('$work/root/usr/share/spira/samples/dome.stl')) > 0"
fi
echo "package OK: $(basename "$deb")"
