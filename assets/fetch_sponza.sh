#!/usr/bin/env bash
# Downloads Crytek Sponza (glTF 2.0, ~51 MiB) into assets/sponza/ so that `vct --scene sponza`
# finds it (the asset search path is $VCT_ASSET_DIR, ./assets, <source>/assets, …).
#
#   assets/fetch_sponza.sh            # into <repo>/assets/sponza
#   assets/fetch_sponza.sh DIR        # into DIR/sponza (then: export VCT_ASSET_DIR=DIR)
#
# Which Sponza: the Capsaicin version (AMD GPUOpen CapsaicinTestMedia, commit affd175…, CC BY 3.0),
# because it is the one vct's tests, camera presets and benchmarks are written for: 4 cameras
# (CameraMain, CameraAlternate, CameraBalcony, CameraAlcove), 262,087 triangles, alpha-masked
# plants/chains. The Khronos glTF-Sample-Assets "Sponza" is the same building but has no cameras,
# another scale and other file names; `vct --scene path/to/its/Sponza.gltf` loads it fine, but the
# Sponza test expects this version. The upstream glTF references DDS textures and an AMD
# extension that core glTF loaders reject, so the script patches it exactly as the copy in
# shared/assets was made (SOURCE.txt there): DDS images and the extensions removed, and the three
# curtain textures (missing upstream) taken from the Khronos Sponza's identical JPEGs.
# Every file is checked against its SHA-256, so the result is byte-identical to that copy.
#
# Idempotent: files already present with the right checksum are not downloaded again.
# Needs curl or wget, sha256sum or shasum, and python3 (standard library only).
set -euo pipefail

here="$(cd "$(dirname "$0")" && pwd)"
root="${1:-$here}"
dest="$root/sponza"

capsaicin="https://raw.githubusercontent.com/GPUOpen-LibrariesAndSDKs/CapsaicinTestMedia/affd17570a75370fa4573bcf0816ceb9cb7bfda7/sponza"
khronos_sources=(
  "https://raw.githubusercontent.com/KhronosGroup/glTF-Sample-Assets/main/Models/Sponza/glTF"
  "https://raw.githubusercontent.com/KhronosGroup/glTF-Sample-Models/master/2.0/Sponza/glTF"
  "https://media.githubusercontent.com/media/KhronosGroup/glTF-Sample-Assets/main/Models/Sponza/glTF"
)

# name  sha256  (files copied unchanged from Capsaicin)
read -r -d '' capsaicin_files <<'EOF' || true
Sponza.bin a9c322515510b6eb884cd26c01d921d2ee9f5db5c87a34c16d3bfcb87810ea80
SponzaLicense.txt 5127fe8cc6f5d0771f313ca1def7ad3f5048656628d200873ee0500880319c02
background.png 21f5955648b003a0046ca16054aef2db07901d73662e8b8141e73ba551e06f87
background_normal.png 1da349abdfc10a11c64147bb68c5228cbf2f6c7be690c86e23836fb82eb64a57
chain_texture.png d864cc6dae4d89e1529a565c8a8c5ef79e34214ac49c5748407caad64818936f
chain_texture_normal.png e4ea75def2720faf4464765fe1bdfa2b64c4e0a5b775a51de0c65c19c946b6a8
lion.png 13c763cb8d01e781121180a2f0c7ddc6c672d0a146ffc1359a5795dba99db5c2
lion_normal.png 617433722dd6be6b992692ced0848b7cdcaf51fc6ff88154f897d172e2daf4d2
spnza_bricks_a_diff.png 6653d814e78df5b1d72bff0bc4f055b19f40c60125368c66f706862a77b11e19
spnza_bricks_a_normal.png a238a0543a5a9dcfa95f30dd2caf06aa49a1dab6cfcecfb36f5baadbac5f0043
sponza_arch_diff.png 1a2e127ce784d2d4f061eae58a780cdcc8daba6c0f254d06e5494e41d4874ff2
sponza_arch_normal.png d7666cbf0f94f63b270f5f19496c59080f223708c0e3c4b1ec0c106f1ffbdd6e
sponza_ceiling_a_diff.png 6d6ff12242bd2b0680c45b27d0234cb4fc636959a2575f29dd6eb02251348f4c
sponza_column_a_diff.png 13c3511250c790ad260845ffd5d56f4622bb3760316831403c3cc182bcf40095
sponza_column_a_normal.png 8afe51aabd55640818b1885972a9d451d04d26dcbc6cfc9b11a478548c9db0e8
sponza_column_b_diff.png e893c9f0a8ca1cb7b649476eaa6ce98ece4d82b447f2a9858dbf0be4ce05c8e1
sponza_column_b_normal.png 7e05e25f6207f44f49a00c0a13bac7cc0f110fd505223d12050156837ceb94a8
sponza_column_c_diff.png eaf9050e0cb05bc5184b4fc7108085036e049ca6a3a93c0b11ed8e920831472d
sponza_column_c_normal.png 81ef58a4ff92780e3d4073240f958f11e3dba0882f649765f77975cf358f82ae
sponza_details_diff.png 01012e0e81c20b10856dd34476069aadf1270cedd47e13b2760ae7dec341a7ab
sponza_fabric_blue_diff.png b7398d4f96ac101b92a42f8e093754fa239bb80e0038727e49574abed5473c20
sponza_fabric_diff.png 1fe1ee45005ddcbcde414096c1018c9296e5dfed528ecc99f9ce7d82862fd963
sponza_fabric_green_diff.png eb009dd943c52da29e3d7dd4d30e12a912769ffc7659e97dba7a2483fa79c6c3
sponza_flagpole_diff.png c65b8651f12a05063118a91bd2c1ebb37a403936bb2b79226cf842917ebfbcbe
sponza_floor_a_diff.png ec677f8d95abc307a7551a501ed20c9cd79bbc38d41963a7d74a35d096d2f1c4
sponza_roof_diff.png be5c0e86671a709c5d2f87820f92414bf4c069c5041d2fb548f8bf130f7616dd
sponza_thorn_diff.png c941104dc0ca563ccf5c234c77f364357e8a47ef7483088417fc842c92785258
sponza_thorn_normal.png 46f26eff378234973c93654aeaad0678ee9ba548e5ea49775dee77787e50ea2a
vase_dif.png 141d957726bb80708e3210d481c82d4038016cc31e414c541eea76d61e600bd5
vase_hanging.png 310b171c5508c7f1df97cc87ebb2139141f4fbf6cd65d6cf1675e92ed64521b6
vase_normal.png b908734cae1232539ade3e7f620b4015b3d77a14b680aa474861d2cace57f6f9
vase_plant.png 39402f8018d41ccd18610a2acbf85180e5cf59b21f80d4d20c0b217c02887fa3
vase_round.png 5ee2138dc016aff582e50c2725b7749cdf0681537147d3cd9034e0d10414fb7c
vase_round_normal.png 3d1200422612ea4121b3da72e13a79cb6d71089d349da340c6a5404e31af0a24
EOF

# local name  khronos name  sha256  (curtains: the Khronos Sponza's JPEGs of the same images)
read -r -d '' curtain_files <<'EOF' || true
sponza_curtain_diff.jpg 11474523244911310074.jpg 23c32277c33d8eac091cd73daf81561ebe3640eede49b037546ed5c244a01347
sponza_curtain_blue_diff.jpg 17876391417123941155.jpg 005b774a968c1f6af00e4bf97afd668a6a045126a94f524df722ba19edc77d61
sponza_curtain_green_diff.jpg 9288698199695299068.jpg 7f55814430f289e89c7d675c3db925eee904fbc566ff83f4b49904de53138e98
EOF

gltf_sha256=a3b1cdf88d97894efdb3d1f33c6d988c68d7d7c165477aed38f768aede33d9d8

die() { echo "fetch_sponza: error: $*" >&2; exit 1; }

if command -v curl >/dev/null; then
  download() { curl -fsSL --retry 3 --connect-timeout 20 -o "$2" "$1"; }
elif command -v wget >/dev/null; then
  download() { wget -q --tries=3 --timeout=20 -O "$2" "$1"; }
else
  die "needs curl or wget"
fi
if command -v sha256sum >/dev/null; then
  sha256() { sha256sum "$1" | cut -d' ' -f1; }
elif command -v shasum >/dev/null; then
  sha256() { shasum -a 256 "$1" | cut -d' ' -f1; }
else
  die "needs sha256sum or shasum"
fi
command -v python3 >/dev/null || die "needs python3 (to patch Sponza.gltf)"

ok() { [ -f "$1" ] && [ "$(sha256 "$1")" = "$2" ]; }

mkdir -p "$dest"
tmp="$(mktemp -d "$dest/.download.XXXXXX")"
trap 'rm -rf "$tmp"' EXIT
fetched=0

# Downloads $1 (one of several URLs, tried in turn) to $dest/$2 when it is not already there with
# SHA-256 $3.
fetch() {
  local name="$2" want="$3" url
  ok "$dest/$name" "$want" && return 0
  echo "fetch_sponza: downloading $name"
  for url in $1; do
    rm -f "$tmp/$name"
    if download "$url" "$tmp/$name" 2>/dev/null && ok "$tmp/$name" "$want"; then
      mv "$tmp/$name" "$dest/$name"
      fetched=$((fetched + 1))
      return 0
    fi
  done
  die "could not download $name with SHA-256 $want (tried: $1)"
}

while read -r name sum; do
  [ -n "$name" ] && fetch "$capsaicin/$name" "$name" "$sum"
done <<<"$capsaicin_files"

while read -r name upstream sum; do
  [ -n "$name" ] || continue
  urls=""
  for base in "${khronos_sources[@]}"; do urls="$urls $base/$upstream"; done
  fetch "$urls" "$name" "$sum"
done <<<"$curtain_files"

if ! ok "$dest/Sponza.gltf" "$gltf_sha256"; then
  echo "fetch_sponza: downloading and patching Sponza.gltf"
  download "$capsaicin/Sponza.gltf" "$tmp/upstream.gltf" || die "could not download $capsaicin/Sponza.gltf"
  python3 - "$tmp/upstream.gltf" "$tmp/Sponza.gltf" <<'PY'
import json, sys
with open(sys.argv[1], encoding="utf-8") as f:
    g = json.load(f)
# Core glTF only: drop MSFT_texture_dds / AMD_split_roughnessMetallic.
g.pop("extensionsUsed", None)
g.pop("extensionsRequired", None)
# DDS images and the textures that only had a DDS source come last; keep the PNG ones (0..34).
keep = [i for i, image in enumerate(g["images"]) if not image["uri"].lower().endswith(".dds")]
assert keep == list(range(len(keep))), "DDS images are not all at the end"
g["images"] = g["images"][: len(keep)]
textures = []
for t in g["textures"]:
    t.pop("extensions", None)
    if "source" in t:
        textures.append(t)
assert len(textures) == len(keep) and all(t["source"] < len(keep) for t in textures)
g["textures"] = textures
for m in g["materials"]:
    m.pop("extensions", None)
# The three curtain textures are the Khronos JPEGs.
for image in g["images"]:
    if image["uri"] in ("sponza_curtain_diff.png", "sponza_curtain_blue_diff.png",
                        "sponza_curtain_green_diff.png"):
        image["uri"] = image["uri"][:-4] + ".jpg"
        image["mimeType"] = "image/jpeg"
with open(sys.argv[2], "w", encoding="utf-8") as f:
    f.write(json.dumps(g, indent=2) + "\n")
PY
  if ! ok "$tmp/Sponza.gltf" "$gltf_sha256"; then
    echo "fetch_sponza: warning: the patched Sponza.gltf differs from the reference copy" \
         "(SHA-256 $(sha256 "$tmp/Sponza.gltf")); it should still load, but check the" \
         "Sponza test" >&2
  fi
  mv "$tmp/Sponza.gltf" "$dest/Sponza.gltf"
  fetched=$((fetched + 1))
fi

cat >"$dest/SOURCE.txt" <<'EOF'
Crytek Sponza (Frank Meinl / Crytek, based on Marko Dabrovic's model; modifications by Morgan
McGuire and Matthew Oliver), glTF 2.0 from AMD GPUOpen CapsaicinTestMedia commit
affd17570a75370fa4573bcf0816ceb9cb7bfda7 (sponza/), CC BY 3.0 (see SponzaLicense.txt).
Fetched by vct's assets/fetch_sponza.sh: Sponza.gltf patched to core glTF 2.0 (DDS images,
MSFT_texture_dds and AMD_split_roughnessMetallic removed; the three curtain textures, missing
upstream, are the identical images from the Khronos glTF Sample Models Sponza as JPEGs).
EOF

if [ "$fetched" -eq 0 ]; then
  echo "fetch_sponza: Sponza is already complete in $dest"
else
  echo "fetch_sponza: Sponza is in $dest ($fetched files downloaded)"
fi
if [ "$root" != "$here" ]; then
  echo "fetch_sponza: set VCT_ASSET_DIR=$root so that vct finds it"
fi
