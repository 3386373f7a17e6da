#!/usr/bin/env bash
# Makes the PNG files of every colour type and bit depth that Texture.PngFilesReadAsTheCodecReadsThem
# reads both ways (libpng in core/png_file.cpp, OpenImageIO through the codec module). Run by
# hand (needs ImageMagick's convert); the files are committed. Random 16-bit noise, so that
# each 16-bit file holds values between two 8-bit ones, where rounding could differ; half
# the pixels opaque, the others of any alpha.
set -euo pipefail
cd "$(dirname "$0")"
IM=/usr/bin/convert
src=$(mktemp --suffix=.png)
trap 'rm -f "$src"' EXIT
$IM -size 37x23 -seed 7 xc: +noise Random -depth 16 -define png:color-type=6 \
    \( -size 37x23 -seed 9 xc: +noise Random -channel R -separate -evaluate Multiply 2 \) -compose CopyOpacity -composite "$src"
png() { $IM "$src" "$@"; }
png -alpha off -depth 8 -define png:color-type=2 rgb8.png
png -depth 8 -define png:color-type=6 rgba8.png
png -alpha off -depth 16 -define png:color-type=2 rgb16.png
png -depth 16 -define png:color-type=6 rgba16.png
png -alpha off -colorspace Gray -depth 8 -define png:color-type=0 grey8.png
png -alpha off -colorspace Gray -depth 16 -define png:color-type=0 grey16.png
png -colorspace Gray -depth 8 -define png:color-type=4 greyalpha8.png
png -alpha off -colorspace Gray -depth 4 -define png:color-type=0 -define png:bit-depth=4 grey4.png
png -alpha off -colorspace Gray -depth 2 -define png:color-type=0 -define png:bit-depth=2 grey2.png
png -alpha off -colorspace Gray -monochrome -define png:color-type=0 -define png:bit-depth=1 grey1.png
png -alpha off -colors 200 -define png:color-type=3 palette8.png
png -alpha off -colors 13 -define png:color-type=3 -define png:bit-depth=4 palette4.png

png -alpha off -depth 8 -define png:color-type=2 -interlace PNG rgb8_interlaced.png
png -depth 16 -define png:color-type=6 -interlace PNG rgba16_interlaced.png
./make_exact.py
