#!/usr/bin/env bash
# Makes the JPEG files Texture.JpegFilesReadAsTheCodecReadsThem reads both ways (libjpeg in
# core/jpeg_file.cpp, OpenImageIO through the codec module): each chroma subsampling,
# progressive, with restart markers, grey, CMYK (left to the codec), at sizes that are not
# whole blocks. Run by hand (ImageMagick's convert, which scripts/setup.sh installs); the
# files are committed. grid.jpg: the texture quad.obj wears.
set -euo pipefail
cd "$(dirname "$0")"
IM=/usr/bin/convert
grid=../../../assets/models/uv_grid.png
$IM "$grid" -resize 64x64 -quality 90 -strip grid.jpg
$IM "$grid" -resize 37x23! -quality 85 -sampling-factor 4:2:0 -strip s420.jpg
$IM "$grid" -resize 37x23! -quality 85 -sampling-factor 4:2:2 -strip s422.jpg
$IM "$grid" -resize 37x23! -quality 95 -sampling-factor 4:4:4 -strip s444.jpg
$IM "$grid" -resize 41x29! -quality 80 -interlace JPEG -strip progressive.jpg
$IM "$grid" -resize 53x31! -quality 80 -define jpeg:restart-interval=2 -strip restart.jpg
$IM "$grid" -resize 37x23! -colorspace Gray -quality 85 -strip grey.jpg
$IM "$grid" -resize 37x23! -colorspace CMYK -quality 85 -strip cmyk.jpg
