#!/usr/bin/env bash
# Extracts a chosen subset of the STEP models of Debian's kicad-packages3d (thousands of real
# electronic components; about 380 MB to download, 5.5 GB installed) without installing the
# package: `apt-get download` fetches the .deb, `dpkg-deb --fsys-tarfile` streams its files
# (what `dpkg -x` does) and tar extracts only the chosen models. For large and cluster runs,
# not for CI:
#   holebench run --mesh DIR --case 'file/*' ...
#
# Usage: scripts/fetch_kicad_subset.sh [--out DIR] [--per-library N] [LIBRARY...]
#   --out DIR          where the .step files go, flat (default: build/kicad-step)
#   --per-library N    the first N models by name of each library (default: 2)
#   LIBRARY...         KiCad 3D libraries, e.g. Package_SO (default: the list below)
# The .deb is kept in DIR/.deb/ so a second run does not download it again. Every file name
# is unique across libraries in the package, so a model's stem is its case id's <stem>.
set -euo pipefail

out="build/kicad-step"
per_library=2
libraries=()
while [ $# -gt 0 ]; do
  case "$1" in
    --out) out="$2"; shift 2 ;;
    --per-library) per_library="$2"; shift 2 ;;
    -h|--help) sed -n '2,16p' "$0"; exit 0 ;;
    *) libraries+=("$1"); shift ;;
  esac
done
if [ ${#libraries[@]} -eq 0 ]; then
  # Mechanical shapes of several kinds: flat packages, pins and bodies, cylinders, housings.
  libraries=(Package_SO Package_QFP Package_DFN_QFN Package_TO_SOT_SMD Package_TO_SOT_THT
             Package_DIP Connector_PinHeader_2.54mm Connector_USB Capacitor_THT Inductor_SMD
             Button_Switch_THT Crystal TerminalBlock_Phoenix Fuse)
fi

deb_dir="$out/.deb"
mkdir -p "$deb_dir"
deb=$(ls "$deb_dir"/kicad-packages3d_*.deb 2>/dev/null | head -n 1 || true)
if [ -z "$deb" ]; then
  echo "fetch_kicad_subset: downloading kicad-packages3d (about 380 MB) into $deb_dir" >&2
  (cd "$deb_dir" && apt-get download kicad-packages3d) || {
    echo "fetch_kicad_subset: apt-get download failed (run apt-get update as root?)" >&2
    exit 1
  }
  deb=$(ls "$deb_dir"/kicad-packages3d_*.deb | head -n 1)
fi

# The package's STEP files, then the first N of each chosen library, sorted by name (so the
# same arguments give the same subset).
listing="$deb_dir/step-files.txt"
[ -s "$listing" ] || dpkg-deb --fsys-tarfile "$deb" | tar -t | grep -iE '\.(step|stp)$' | sort > "$listing"
chosen="$deb_dir/chosen.txt"
: > "$chosen"
for library in "${libraries[@]}"; do
  matches=$(grep -F "/$library.3dshapes/" "$listing" | head -n "$per_library" || true)
  if [ -z "$matches" ]; then
    echo "fetch_kicad_subset: no STEP models in library $library" >&2
    continue
  fi
  printf '%s\n' "$matches" >> "$chosen"
done
[ -s "$chosen" ] || { echo "fetch_kicad_subset: nothing chosen" >&2; exit 1; }

staging="$deb_dir/extract"
rm -rf "$staging"
mkdir -p "$staging"
dpkg-deb --fsys-tarfile "$deb" | tar -x -C "$staging" -T "$chosen"
while IFS= read -r file; do
  cp "$staging/$file" "$out/"
done < "$chosen"
rm -rf "$staging"
echo "fetch_kicad_subset: $(wc -l < "$chosen") STEP models in $out" >&2
