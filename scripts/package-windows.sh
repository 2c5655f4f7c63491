#!/usr/bin/env bash
# The Windows zip, made on Linux: cross-builds fractalis for Windows (scripts/windows-build.sh),
# installs it into a folder laid out as on Linux — bin\fractalis.exe, its helpers in
# libexec\fractalis, the scenes in lib\fractalis\plugins, the camera paths in share\fractalis,
# the SDK (include\, lib\cmake\FractalisSDK, share\doc\fractalis-sdk) — with README.txt
# (packaging/windows/) and an example settings file, and zips that folder:
#   build-windows/fractalis-<version>-windows-x64.zip
# Prints the zip's path. Everything is linked in (the MinGW runtime, SDL2, libpng, zlib): the
# only DLL it needs from the PC is OpenCL.dll, which README.txt says where to get.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
source "$FRACTALIS_ROOT/scripts/windows-build.sh"

fractalis_windows_build zip
version="$(sed -n 's/^CMAKE_PROJECT_VERSION:STATIC=//p' "$FRACTALIS_BUILD/CMakeCache.txt")"
name="fractalis-$version-windows-x64"
stage="$FRACTALIS_BUILD/package"
zip_file="$FRACTALIS_BUILD/$name.zip"
rm -rf "$stage"
mkdir -p "$stage"
cmake --install "$FRACTALIS_BUILD" --prefix "$stage/$name" >/dev/null
cp "$FRACTALIS_ROOT/packaging/windows/README.txt" "$stage/$name/README.txt"
cp "$FRACTALIS_ROOT/config/default.toml" "$stage/$name/settings-example.toml"
# Windows' editors and consoles expect CRLF in text files.
sed -i 's/$/\r/' "$stage/$name/README.txt" "$stage/$name/settings-example.toml"
# Written beside, then renamed: an interrupted run never leaves a half zip under the real name.
rm -f "$zip_file.part"
(cd "$stage" && zip -qr -X "$zip_file.part" "$name")
mv -f "$zip_file.part" "$zip_file"
echo "fractalis: wrote $zip_file ($(du -h "$zip_file" | cut -f1))" >&2
echo "$zip_file"
