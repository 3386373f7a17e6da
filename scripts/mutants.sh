#!/usr/bin/env bash
# Plants known bugs ("mutants") one at a time in a scratch copy of the tree, builds the
# test binary that should notice, runs the tests that should fail, and counts: a mutant
# whose tests still pass is MISSED. Every mutant must be caught; see docs/testing.md.
# Slow (a rebuild per mutant), so not part of CI: run it after changing tests or code
# that a mutant below touches, and add a mutant with each bug a test was written for.
#   scripts/mutants.sh [NAME_FILTER]     e.g. scripts/mutants.sh refraction
set -uo pipefail
set -f  # test filters like 'Transform.*' are not file patterns
cd "$(dirname "$0")/.."
filter=${1:-}
scratch=${RTVIEW_MUTANTS_DIR:-/tmp/rtview-mutants}
src=$scratch/src
build=$scratch/build
mkdir -p "$src"
# The tracked and new files as they are now, uncommitted changes included. Compared by
# content, and a changed file gets a new time (not its own), so that the build sees it
# as newer than objects left by an earlier run.
git ls-files -co --exclude-standard -z |
    rsync -rlpD --checksum --no-times --delete --from0 --files-from=- ./ "$src/"
cmake -S "$src" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DRTVIEW_BUILD_VIEWER=ON \
    >"$scratch/configure.log" 2>&1 || { cat "$scratch/configure.log"; exit 1; }

caught=0 missed=0 broken=0
missed_names=()

# mutant NAME FILE FROM TO TARGET TEST_COMMAND...
# FROM must occur in FILE exactly once; TEST_COMMAND runs in the build directory and
# must fail for the mutant to count as caught.
mutant() {
    local name=$1 file=$2 from=$3 to=$4 target=$5
    shift 5
    [ -n "$filter" ] && [[ $name != *$filter* ]] && return
    cp "$src/$file" "$scratch/original"
    if ! python3 - "$src/$file" "$from" "$to" <<'EOF'
import sys
path, old, new = sys.argv[1], sys.argv[2], sys.argv[3]
text = open(path).read()
if text.count(old) != 1:
    sys.exit(f"{path}: the text to change occurs {text.count(old)} times, not once")
open(path, "w").write(text.replace(old, new))
EOF
    then
        echo "BROKEN $name: could not be planted (the code moved: update scripts/mutants.sh)"
        broken=$((broken + 1))
        return
    fi
    if ! cmake --build "$build" --target "$target" >"$scratch/$name.build.log" 2>&1; then
        # A mutant that does not compile proves nothing about the tests.
        echo "BROKEN $name: does not compile (see $scratch/$name.build.log)"
        broken=$((broken + 1))
    elif (cd "$build" && "$@") >"$scratch/$name.test.log" 2>&1; then
        echo "MISSED $name: the tests pass with it ($*)"
        missed=$((missed + 1))
        missed_names+=("$name")
    else
        echo "caught $name"
        caught=$((caught + 1))
    fi
    cp "$scratch/original" "$src/$file"
}

unit() { echo tests/rt_tests --gtest_filter="$1"; }
gl=(env RTVIEW_GL_DEBUG=1 tests/rt_gl_tests)

# The eight the audit planted (issue 18), then others.
mutant transform-normal core/transform.cpp \
    't.normal = glm::transpose(glm::inverse(linear));' 't.normal = glm::inverse(linear);' \
    rt_tests $(unit 'Transform.*')
mutant refraction-indices-swapped core/tracer.cpp \
    'sp.normal, crossing.eta_from, crossing.eta_to)' 'sp.normal, crossing.eta_to, crossing.eta_from)' \
    rt_tests $(unit 'Refraction*:Refract.*')
mutant tir-black core/tracer.cpp \
    'return reflected(r, sp, mirrored, counts);' 'return vec3(0.0f);' \
    rt_tests $(unit 'Refraction*')
# The sRGB bytes of a PNG (core/image.cpp's table): the formula's, bit for bit.
mutant srgb8-bucket-next-ignored core/image.cpp \
    'b.byte + (c >= b.next ? 1u : 0u)' 'b.byte' \
    rt_tests $(unit 'Image.*')
mutant srgb8-boundary-float-rounds-down core/image.cpp \
    'b.byte + (c >= b.next ? 1u : 0u)' 'b.byte + (c > b.next ? 1u : 0u)' \
    rt_tests $(unit 'Image.*')
mutant srgb8-bisection-skips-a-float core/image.cpp \
    'lo = mid + 1;' 'lo = mid + 2;' \
    rt_tests $(unit 'Image.*')
# Image files: PNG by libpng (core/png_file.cpp), EXR through the codec module.
mutant image-io-png-rows-bottom-first core/png_file.cpp \
    'png_write_row(png, rgb + static_cast<std::size_t>(y) * row);' \
    'png_write_row(png, rgb + static_cast<std::size_t>(height - 1 - y) * row);' \
    rt_tests $(unit 'Image.*')
mutant image-io-exr-rows-not-flipped core/image_io.cpp \
    'const auto row_step = -3 * static_cast<std::ptrdiff_t>(image.width);' \
    'const auto row_step = 3 * static_cast<std::ptrdiff_t>(image.width); top_row = &image.at(0, 0).x;' \
    rt_tests $(unit 'Image.*')
mutant image-io-png-write-error-unsaid core/png_file.cpp \
    'if (write_error) return' 'if (false && write_error) return' \
    rt_tests $(unit 'Image.*')
# The codec's EXR work on the caller's thread; the test alone, in its own process (as CTest
# runs it): an earlier EXR in the same process would have started OpenEXR's pool already.
mutant image-io-exr-thread-pool core/image_codec_oiio.cpp \
    'OIIO::attribute("exr_threads", -1);' 'OIIO::attribute("exr_threads", 0);' \
    rt_tests $(unit 'Image.ExrIsReadAndWrittenOnTheCallersThread')
# PNG textures read by libpng as OpenImageIO read them (Texture.PngFilesReadAsTheCodecReadsThem).
mutant png-read-16-bits-cut core/png_file.cpp \
    'return static_cast<std::uint8_t>((v * 255u + 32767u) / 65535u);' \
    'return static_cast<std::uint8_t>(v >> 8);' \
    rt_tests $(unit 'Texture.*')
mutant png-read-trns-dropped core/png_file.cpp \
    'png_set_expand(png);' 'png_set_expand(png); png_set_strip_alpha(png);' \
    rt_tests $(unit 'Texture.*')
mutant png-read-past-the-end core/png_file.cpp \
    'if (n > source->size - source->at)' 'if (false)' \
    rt_tests $(unit 'Texture.*')
# JPEG textures read by libjpeg as OpenImageIO read them (Texture.Jpeg*, Texture.ACutJpeg*).
mutant jpeg-cut-file-said-nothing core/jpeg_file.cpp \
    'if (error.ended_early) {' 'if (false) {' \
    rt_tests $(unit 'Texture.*')
mutant jpeg-fast-inverse-dct core/jpeg_file.cpp \
    'jpeg_start_decompress(&info);' 'info.dct_method = JDCT_IFAST; jpeg_start_decompress(&info);' \
    rt_tests $(unit 'Texture.*')
mutant jpeg-cmyk-not-left-to-the-codec core/jpeg_file.cpp \
    'if (info.jpeg_color_space == JCS_CMYK || info.jpeg_color_space == JCS_YCCK) {' 'if (false) {' \
    rt_tests $(unit 'Texture.*')
# A PLY's body checked before Assimp reads it (core/ply_check.cpp).
mutant ply-ascii-missing-faces-ignored core/ply_check.cpp \
    'if (!lines.next(words))' 'if (!lines.next(words)) return; if (false)' \
    rt_tests $(unit 'PlyStl.*')
mutant ply-ascii-words-taken-for-numbers core/ply_check.cpp \
    'if (!is_number(w))' 'if (false)' \
    rt_tests $(unit 'PlyStl.*')
mutant ply-binary-list-length-byte-order core/ply_check.cpp \
    'const int byte = h.format == Format::kBig ? k : p.count_bytes - 1 - k;' \
    'const int byte = h.format != Format::kBig ? k : p.count_bytes - 1 - k;' \
    rt_tests $(unit 'PlyStl.*')
# The item buffer's packed ids (app/gl/framebuffer.h, IdLayout).
mutant packed-ids-mask-one-bit-short core/item_buffer.h \
    'std::uint32_t prim_mask() const { return (std::uint32_t{1} << prim_bits) - 1u; }' \
    'std::uint32_t prim_mask() const { return (std::uint32_t{1} << prim_bits) / 2 - 1u; }' \
    rt_gl_tests "${gl[@]}" --gtest_filter='*PackedIds*'
mutant packed-ids-unmasked-in-shader shaders/itembuffer.frag \
    '(prim & ((1u << u_prim_bits) - 1u))' 'prim' \
    rt_gl_tests "${gl[@]}" --gtest_filter='*PackedIds*'
mutant packed-ids-shown-unshifted shaders/present.frag \
    'texture(u_ids, uv).r >> u_ids_shift;' 'texture(u_ids, uv).r;' \
    rt_gl_tests "${gl[@]}" --gtest_filter='*ItemView*'
mutant packed-ids-picked-unshifted app/gl/framebuffer.cpp \
    'return id >> ids_.shader_prim_bits();' 'return id;' \
    rt_gl_tests "${gl[@]}" --gtest_filter='*PackedIds*'
# The raster's draw list leaves out what the camera cannot see (app/gl/gpu_scene.cpp).
mutant cull-left-side-too-far app/gl/gpu_scene.cpp \
    '(beyond(-c.x, c.w) ? 0x01u : 0u)' '(beyond(-c.x, 0.8f * c.w) ? 0x01u : 0u)' \
    rt_gl_tests "${gl[@]}" --gtest_filter='*GpuScene*'
mutant cull-a-corner-enough app/gl/gpu_scene.cpp \
    'outside_all &= outside;' 'outside_all &= outside; if (outside != 0) return false;' \
    rt_gl_tests "${gl[@]}" --gtest_filter='*GpuScene*'
mutant cull-nothing app/gl/gpu_scene.cpp \
    'return outside_all == 0;' 'return outside_all == 0 || true;' \
    rt_gl_tests "${gl[@]}" --gtest_filter='*GpuScene*'
mutant compare-counts-nothing core/compare.cpp \
    'd.pixels_over += largest > threshold;' 'd.pixels_over += 0;' \
    rt_tests $(unit 'Compare.*')
mutant obj-line-off-by-one core/obj_loader.cpp \
    'throw Error(file, "line " + std::to_string(number), what);' \
    'throw Error(file, "line " + std::to_string(number + 1), what);' \
    rt_tests $(unit 'Obj.*')
mutant specular-without-exponent core/tracer.cpp \
    'm.ks * std::pow(r_dot_v, m.shininess)' 'm.ks * r_dot_v' \
    rt_tests $(unit 'Phong.*')
mutant refinement-skips-levels app/viewer/trace_job.cpp \
    'for (std::size_t i = 0; i < request.levels.size(); ++i) {' \
    'for (std::size_t i = request.levels.size() - 1; i < request.levels.size(); ++i) {' \
    rt_viewer_tests tests/rt_viewer_tests --gtest_filter='TraceJob.*'
mutant superseded-result-kept app/viewer/trace_job.cpp \
    'result_.reset();  // an untaken result' '// an untaken result' \
    rt_viewer_tests tests/rt_viewer_tests --gtest_filter='TraceJob.*'
mutant refinement-without-rest app/viewer/refinement.cpp \
    'if (!refine_pending_ || now - last_change_ < kRestSeconds) return {};' \
    'if (!refine_pending_) return {};' \
    rt_viewer_tests tests/rt_viewer_tests --gtest_filter='RefinementSchedule.*'
mutant orbit-about-the-tilted-view-up app/viewer/camera_controller.cpp \
    'frame_v_ = nearest_axis(home_.v);' 'frame_v_ = home_.v;' \
    rt_viewer_tests tests/rt_viewer_tests --gtest_filter='CameraController.*'
mutant switcher-steps-from-the-scene-shown app/viewer/scene_switcher.cpp \
    'const std::filesystem::path from = asked_.empty() ? current_ : asked_;' \
    'const std::filesystem::path from = current_;' \
    rt_viewer_tests tests/rt_viewer_tests --gtest_filter='SceneSwitcher.*'
mutant switcher-controls-ignore-modifiers app/viewer/keys.h \
    'chord.mods == (mods & kChordMods))' '(mods | 1) != 0)' \
    rt_viewer_tests tests/rt_viewer_tests --gtest_filter='Controls.*'
mutant near-plane-ignores-planes app/gl/gpu_scene.cpp \
    'nearest = std::min(nearest, plane_distance(*p, o, camera.eye));' '(void)p;' \
    rt_gl_tests "${gl[@]}" --gtest_filter='*Skimming*'
mutant keys-reach-imgui-focus app/viewer/viewer_input.cpp \
    'if (editing || is_modifier(key) || action == GLFW_RELEASE)
        window_.forward_key(key, scancode, action, mods);
    if (editing) return;' \
    'window_.forward_key(key, scancode, action, mods);
    if (ImGui::GetIO().WantCaptureKeyboard) return;' \
    rtview ctest -R '^gui[.]' --output-on-failure
mutant input-events-collapse-within-a-frame app/gl/window.cpp \
    'if (std::any_of(changed_.begin(), changed_.end(), same)) break;' '(void)same;' \
    rtview ctest -R '^gui[.]' --output-on-failure
mutant shown-trace-takes-late-results app/viewer/refinement.h \
    'if (submitted_ && submitted_->first == id) {' 'if (submitted_) {' \
    rt_viewer_tests tests/rt_viewer_tests --gtest_filter='ShownTrace.*'
mutant diff-against-the-full-raster app/viewer/viewer.cpp \
    'in.view == View::kDiff && coarse' 'false && coarse' \
    rtview ctest -R '^gui[.]' --output-on-failure
mutant ray-tree-without-local-terms core/tracer.cpp \
    'if (recorder_) recorder_->open().local = parts.local;' '' \
    rt_tests $(unit 'RayTree.*')
mutant typed-slider-values-unclamped app/viewer/viewer_panel.cpp \
    'constexpr ImGuiSliderFlags kClamp = ImGuiSliderFlags_AlwaysClamp;' \
    'constexpr ImGuiSliderFlags kClamp = 0;' rtview ctest -R '^gui[.]' --output-on-failure
mutant panel-left-off-screen app/viewer/viewer_panel.cpp \
    '    keep_panel_inside();
' '' rtview ctest -R '^gui[.]' --output-on-failure
mutant gl-debug-not-installed app/gl/debug.cpp \
    'glDebugMessageCallback(on_debug_message, nullptr);' '(void)on_debug_message;' \
    rt_gl_tests "${gl[@]}" --gtest_filter='*ContextIsCoreProfile*'
mutant shadow-feeler-dropped core/tracer.cpp \
    'const bool blocked = scene_.occluded(feeler, t_max, index, sp.cannot_meet_again);' \
    'const bool blocked = false;' \
    rt_tests $(unit 'Shadows.*')
# The renderer's shading of first hits across SIMD lanes (Tracer::shade_found).
mutant shade-lanes-feelers-dropped core/tracer.cpp \
    'if (options_.shadows && lit != 0) lit = visible_lanes' 'if (false) lit = visible_lanes' \
    rt_tests $(unit 'ShadeFound.*')
mutant shade-lanes-one-material-misread core/tracer.cpp \
    'for (int k = 1; k < n; ++k) one_material' 'for (int k = 2; k < n; ++k) one_material' \
    rt_tests $(unit 'ShadeFound.*')
mutant shade-lanes-unlit-added core/tracer.cpp \
    'colour = select(ShadeLanes::mask(lit), colour + term, colour);' 'colour = colour + term;' \
    rt_tests $(unit 'ShadeFound.*')
mutant shade-lanes-viewer-unnormalised core/tracer.cpp \
    'in.to_viewer = -normalize(rows_of(dirs));' 'in.to_viewer = -rows_of(dirs);' \
    rt_tests $(unit 'ShadeFound.*')
mutant shade-lanes-checker-parity core/tracer.cpp \
    '(sum == splat<Float>(0.0f)) | (sum == splat<Float>(2.0f))' '(sum == splat<Float>(0.0f))' \
    rt_tests $(unit 'ShadeFound.*')
mutant shade-lanes-checker-without-colour core/tracer.cpp \
    'field(&SurfacePoint::colour);' 'ShadeLanes::splat(vec3(1.0f));' \
    rt_tests $(unit 'ShadeFound.*')
mutant plane-lanes-direction-misread core/scene.cpp \
    'dir = Lanes3::transpose(dirs, 1);' 'dir = Lanes3::transpose(dirs, 0);' \
    rt_tests $(unit 'ShadeFound.*')
mutant shade-lanes-pattern-of-lane-zero core/tracer.cpp \
    'for (int lane = 0; lane < kPacketWidth; ++lane) rows[lane] = &v[lane < n ? lane : 0].x;' \
    'for (int lane = 0; lane < kPacketWidth; ++lane) rows[lane] = &v[0].x;' \
    rt_tests $(unit 'ShadeFound.*')
mutant select-bits-swapped core/simd.h \
    '_mm256_mask_blend_ps(static_cast<__mmask8>(mask), b, a)' \
    '_mm256_mask_blend_ps(static_cast<__mmask8>(mask), a, b)' \
    rt_tests $(unit 'Simd.*')
mutant packet-triangles-limit-not-lowered core/triangle_packet.h \
    'limit = select_bits(candidates, t, limit);' '' \
    rt_tests $(unit 'TrianglePacket.*:EveryKind/PacketTest.*')
mutant transpose-rows-upper-half-repeats-the-lower core/simd.h \
    'load_row<Floats>(rows[k + 4]), 1);' 'load_row<Floats>(rows[k]), 1);' \
    rt_tests $(unit 'Simd.*')
mutant load-row-of-three-reads-four core/simd.h \
    'return _mm_maskz_loadu_ps(0x7, p);' 'return _mm_loadu_ps(p);' \
    rt_tests $(unit 'Simd.*')
mutant packet-triangles-corners-of-the-first-ray core/mesh_packet.cpp \
    'triangles[((lanes >> lane) & 1u) != 0 ? prims[lane] : first];' 'triangles[first];' \
    rt_tests $(unit 'ScenePackets.*:ItemBuffer.*')
mutant plane-lanes-not-back-on-the-plane core/scene.cpp \
    'p = p - normal * (dot(p, normal) - splat<Float>(plane->offset));' '' \
    rt_tests $(unit 'ShadeFound.*')
mutant plane-lanes-facing-ignored core/scene.cpp \
    '(front >> k) & 1u ? unit : -unit;' 'unit;' \
    rt_tests $(unit 'ShadeFound.*')
mutant plane-lanes-checker-unshifted core/scene.cpp \
    'pattern = pattern + Lanes3::splat(pattern_shift(object, o.material));' 'pattern = pattern;' \
    rt_tests $(unit 'Far*:ShadeFound.*')
mutant shade-lanes-without-bounces core/tracer.cpp \
    'bounces(rays[which[k]], hits[which[k]], sps[k], Path{}, counts, parts);' '' \
    rt_tests $(unit 'ShadeFound.*')
# Scene::surface's shortcuts: a plane's checker axes from the build, one normal
# normalised once.
mutant surface-plane-checker-one-axis core/scene.cpp \
    'vec3(glm::dot(s.p, f.t1), glm::dot(s.p, f.t2), 0.0f)' 'vec3(glm::dot(s.p, f.t1), glm::dot(s.p, f.t1), 0.0f)' \
    rt_tests $(unit 'Scene.*')
mutant surface-smooth-normal-dropped core/scene.cpp \
    'ns = one_normal ? ng : glm::normalize(ns);' 'ns = ng;' \
    rt_tests $(unit 'Scene.*')
mutant pixel-centre-off-by-half core/camera.h \
    'static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f' \
    'static_cast<float>(x), static_cast<float>(y)' \
    rt_tests $(unit 'Camera.*')
mutant srgb-constant core/image.cpp '12.92f * c' '12.0f * c' rt_tests $(unit 'Image.*')
mutant wide-bvh-skips-a-child core/wide_bvh.h \
    'for (mask &= mask - 1; mask != 0; mask &= mask - 1) {' \
    'for (mask &= mask - 1, mask &= mask - 1; mask != 0; mask &= mask - 1) {' \
    rt_tests $(unit '*WideBvh*:*Accel*')
# Nodes of sixteen are compiled only for AVX-512 (auto: an AMD processor that runs it).
if grep -q '^RTVIEW_HOST_AMD_AVX512:INTERNAL=1' "$build/CMakeCache.txt"; then
    mutant node-of-sixteen-loses-its-upper-half core/simd.h \
        'if constexpr (sizeof(V) == 64) return _mm512_cmp_ps_mask(a, b, kPredicate);' \
        'if constexpr (sizeof(V) == 64) return _mm512_cmp_ps_mask(a, b, kPredicate) & 0xffu;' \
        rt_tests $(unit '*WideBvh*:*Accel*')
    mutant packet-node-of-sixteen-loses-its-upper-half core/simd.h \
        'return static_cast<unsigned>(_mm512_movepi32_mask(reinterpret_cast<__m512i>(m)));' \
        'return static_cast<unsigned>(_mm512_movepi32_mask(reinterpret_cast<__m512i>(m))) & 0xffu;' \
        rt_tests $(unit '*Packet*')
    mutant lanes-not-equal-ordered core/simd.h ': _CMP_NEQ_UQ;' ': _CMP_NEQ_OQ;' \
        rt_tests $(unit 'Simd.*')
fi
mutant collapse-splits-one-lane-to-the-left core/wide_bvh.cpp \
    'for (int k = 2; k < N; ++k) {' 'for (int k = 2; k < 2; ++k) {' \
    rt_tests $(unit '*WideBvh*:*Accel*')
mutant collapse-never-spreads-a-subtree core/wide_bvh.cpp \
    'const bool fewer = !(both[j - 1] < cost_[i][j - 2]);' 'const bool fewer = true;' \
    rt_tests $(unit '*WideBvh*:*Accel*')
# The rule for a triangle wholly in front of the origin is now a fast path only: without
# it the plane test in double precision accepts the same hits (the fan's slivers), so a
# mutant that drops it changes nothing a test can see but the time.
mutant triangle-plane-test-left-out core/triangle4.h \
    'return sure | plane.lanes;' 'return sure;' \
    rt_tests $(unit 'Watertight.*')
mutant triangle-plane-test-t-of-the-wrong-sign core/triangle4.h \
    'const double t_exact = side *' 'const double t_exact = -side *' \
    rt_tests $(unit 'Watertight.*')
mutant packet-unsure-rays-not-traced-again core/mesh_packet.cpp \
    'for (unsigned m = unsure; m != 0;' 'for (unsigned m = 0u; m != 0;' \
    rt_tests $(unit 'Watertight.*')
mutant packet-unsure-feelers-not-traced-again core/mesh_packet.cpp \
    'for (unsigned m = unsure & ~blocked; m != 0;' 'for (unsigned m = 0u; m != 0;' \
    rt_tests $(unit 'Watertight.*')
mutant collapse-right-costs-read-a-lane-off core/wide_bvh.cpp \
    'right.data() + N - k,' 'right.data() + N - k + 1,' \
    rt_tests $(unit '*WideBvh*')
mutant collapse-split-named-a-lane-off core/wide_bvh.cpp \
    'k_best = cheaper ? Mask{} + k : k_best;' 'k_best = cheaper ? Mask{} + (k - 1) : k_best;' \
    rt_tests $(unit '*WideBvh*')
mutant collapse-last-split-tried-left-out core/wide_bvh.cpp \
    'for (int k = 2; k < N; ++k) {' 'for (int k = 2; k < N - 1; ++k) {' \
    rt_tests $(unit '*WideBvh*')
mutant collapse-gives-the-right-child-one-lane core/wide_bvh.cpp \
    'lanes_of(tree_[index].first, end, N - split_[index][0], l);' \
    'lanes_of(tree_[index].first, end, 1, l);' \
    rt_tests $(unit '*WideBvh*:*Accel*')
mutant pair-test-swaps-its-packs core/triangle4.h \
    '_mm256_set_m128(b.v[vertex][axis], a.v[vertex][axis])' \
    '_mm256_set_m128(a.v[vertex][axis], b.v[vertex][axis])' \
    rt_tests $(unit 'Triangle4.*')
mutant leaf-loop-lane-without-its-pack core/mesh.h \
    'h.lane += static_cast<int>(kTriangle4Lanes * k);' 'h.lane += 0;' \
    rt_tests $(unit 'Triangle4.*')
mutant leaf-kept-whole-where-a-split-pays core/bvh.cpp \
    'Bvh::kKeepLeaf * bounds.box.half_area()' '0.0f * bounds.box.half_area()' \
    rt_tests $(unit 'Bvh.*')
mutant bvh-leaf-left-in-scratch core/bvh.cpp \
    'if (r != refs) std::copy(r + begin, r + end, refs + begin);' \
    'if (false) std::copy(r + begin, r + end, refs + begin);' \
    rt_tests $(unit '*Bvh*:*Accel*')
mutant bvh-leaf-order-unsorted core/bvh.cpp \
    'return a.index() < b.index(); });' 'return false; });' \
    rt_tests $(unit 'Bvh.TheTreeIsTheSameOnAnyNumberOfThreads')
mutant small-node-sort-reverses-negatives core/bvh.cpp \
    '(bits & 0x80000000u) != 0 ? ~bits : bits | 0x80000000u' \
    '(bits & 0x80000000u) != 0 ? bits : bits | 0x80000000u' \
    rt_tests $(unit 'Bvh.*')
mutant small-node-sort-without-ties core/bvh.cpp \
    'return std::uint64_t{ordered} << 32 | p.index();' 'return std::uint64_t{ordered} << 32;' \
    rt_tests $(unit 'Bvh.*')
mutant binned-along-the-widest-axis-only core/bvh.cpp \
    'end - begin <= kAllAxes ? -1 : widest' 'widest' \
    rt_tests $(unit 'Bvh.*')
mutant partition-forgets-the-centres core/bvh.cpp \
    'grow_one_of(on_left, on_right, l, p.centre2());
                left += l;' 'left += l;' \
    rt_tests $(unit 'Bvh.*:*Accel*')
mutant parallel-partition-forgets-the-centres core/bvh.cpp \
    'grow_one_of(on_left, on_right, l, p.centre2());
            }' '}' \
    rt_tests $(unit 'Bvh.*:*Accel*')
mutant centres-grown-on-the-wrong-side core/bvh.cpp \
    'on_left.grow(l != 0 ? c : inf, l != 0 ? c : ninf);' \
    'on_left.grow(l != 0 ? inf : c, l != 0 ? ninf : c);' \
    rt_tests $(unit 'Bvh.*:*Accel*')
mutant cut-boxes-split-one-bin-late core/bvh.cpp \
    '(b <= best.bin ? best.left : best.right)' '(b <= best.bin + 1 ? best.left : best.right)' \
    rt_tests $(unit 'Bvh.*:*Accel*')
mutant spare-pack-lanes-left-as-they-were core/mesh.cpp \
    'for (std::uint32_t i = leaf.count; i % kTriangle4Lanes != 0; ++i) {' \
    'for (std::uint32_t i = leaf.count; false; ++i) {' \
    rt_tests $(unit '*AccelTest.ARebuildLeavesNoEarlierTriangleBehind*')
mutant glsl-specular-dropped shaders/phong.frag \
    'colour += visible * (u_kd * c * n_dot_l + specular) * u_light_colour[i];' \
    'colour += visible * (u_kd * c * n_dot_l) * u_light_colour[i];' \
    rt_gl_tests "${gl[@]}" --gtest_filter='*RasterEqualsLocal*'
mutant far-scenes-not-rebased core/scene_loader_shared.h \
    'constexpr double kFarFromOrigin = 4096.0;' 'constexpr double kFarFromOrigin = 1e300;' \
    rt_tests $(unit 'Far.*')
mutant nan-rays-enter-boxes core/ray.h \
    'return sum == 0.0f;  // x * 0 is NaN' 'return sum == sum || true;  // x * 0 is NaN' \
    rt_tests $(unit 'Far.*')
mutant repeated-faces-kept core/obj_loader.cpp \
    'if (const std::size_t dropped = drop_duplicate_triangles(data.mesh))' \
    'if (const std::size_t dropped = 0)' rt_tests $(unit 'Obj.*')
mutant nan-pixels-not-counted core/compare.cpp \
    'if (!finite(a) || !finite(b)) return vec3(1.0f);' 'if (false) return vec3(1.0f);' \
    rt_tests $(unit 'Compare.*')
mutant checker-parity-wrong core/material.h \
    'return sum == 0.0f || sum == 2.0f ? colour_a : colour_b;' \
    'return sum == 0.0f ? colour_a : colour_b;' \
    rt_tests $(unit 'Checker.*')

mutant stale-mesh-hit-kept core/shapes.h \
    'if (t) hit = Hit{*t, hit.object, 0, 0.0f, 0.0f};' 'if (t) hit.t = *t;' \
    rt_tests $(unit 'Scene.*')
mutant light-on-surface-nan core/tracer.cpp \
    'if (!(distance > 0.0f) || !std::isfinite(distance)) continue;' '' \
    rt_tests $(unit 'Phong.*')
mutant near-light-behind-offset-dark core/tracer.cpp \
    'return glm::dot(from_surface, sp.geometric_normal) > 0.0f ?' 'return false ?' \
    rt_tests $(unit 'Far.*:Shadows.*')
mutant egl-display-terminated-early app/gl/context_egl.cpp \
    'display_refs().release(display_);' 'eglTerminate(display_);' \
    rt_gl_tests "${gl[@]}" --gtest_filter='GlContexts.*'
mutant item-buffer-tutorial-triangle core/mesh.cpp \
    '    hit.t = h.t;' '    hit.t = h.t * (1.0f + 1e-6f);' \
    rt_tests $(unit 'Triangle.*')

mutant gl-handle-never-deletes app/gl/handle.h \
    'if (id_ != 0) Kind::destroy(id_);' '(void)&Kind::destroy;' \
    rt_gl_tests "${gl[@]}" --gtest_filter='*LeakNoGlNames*'
mutant glass-nesting-ignored core/medium.h \
    'Crossing c{ior(), 1.0f, *this};' 'Crossing c{1.0f, 1.0f, *this};' \
    rt_tests $(unit 'Refraction*:MediumStack.*')

# The explain map: a term that no longer sums (shadow's sign), ids compared without the
# item buffer's +1 (every pixel a geometry pixel), and the threshold ignored (no pixel
# without a cause).
mutant explain-shadow-sign core/explain.cpp \
    't.shadow = (traced.local - traced.unblocked) - tricks.shadow;' 't.shadow = (traced.unblocked - traced.local) - tricks.shadow;' \
    rt_tests $(unit 'Explain.*')
mutant explain-ids-off-by-one core/explain.cpp \
    'traced.object == PrimaryParts::kNoObject ? ItemBuffer::kEmpty : traced.object + 1;' \
    'traced.object == PrimaryParts::kNoObject ? ItemBuffer::kEmpty : traced.object;' \
    rt_tests $(unit 'Explain.*')
mutant explain-no-threshold core/explain.cpp \
    'if (!(displayed_difference > kNoneThreshold)) return Cause::kNone;' \
    'if (displayed_difference < 0.0f) return Cause::kNone;' \
    rt_tests $(unit 'Explain.*')
mutant ray-segments-miss-length core/ray_tree.cpp \
    's.b = n.origin + miss_length * unit;
            s.miss = true;' 's.b = n.origin + unit;
            s.miss = true;' \
    rt_tests $(unit 'RayTree.*')

# Issue 15 and what the tiny-scene check found.
mutant item-buffer-lanes-unmasked core/mesh.cpp \
    '1u << (at % kTriangle4Lanes));' '0xfu);' \
    rt_tests $(unit 'Triangle.*')
mutant shared-ids-written-by-lines app/gl/raster_renderer.cpp \
    'if (drawing_ids_) drawing_ids_->draw_ids(false);' '' \
    rt_gl_tests "${gl[@]}" --gtest_filter='*TheColourPassDrawsTheSameItemBuffer*'
mutant edge-run-trusts-any-hit core/item_buffer_step.cpp \
    'if (hits[lane].found() && hits[lane].object + 1 == ib.object_id(at + lane))' \
    'if (hits[lane].found())' \
    rt_tests $(unit 'ItemBuffer.*')
mutant edge-run-leaves-the-meshes-out core/item_buffer_step.cpp \
    'if (mesh_count == 0) return on_edges;' 'return on_edges;' \
    rt_tests $(unit 'ItemBuffer.*')
mutant edge-run-tests-only-the-edge core/item_buffer_step.cpp \
    'scene.intersect_among(around.data(), count, lanes, hits, open);' \
    'scene.intersect_among(around.data(), count, lanes, hits, open & ~left);' \
    rt_tests $(unit 'ItemBuffer.*')
mutant whole-packet-misses-named core/scene.cpp \
    'hits[lane].object = on ? object : kNoObject;' 'hits[lane].object = object;' \
    rt_tests $(unit 'ItemBuffer.*:ScenePackets.*')
mutant whole-packet-misses-keep-their-t core/scene.cpp \
    'hits[lane].t = on ? out.t[lane] : kInfinity;' 'hits[lane].t = out.t[lane];' \
    rt_tests $(unit 'ItemBuffer.*:ScenePackets.*')
mutant whole-packet-barycentrics-swapped core/scene.cpp \
    'hits[lane].b1 = on ? out.b1[lane] : 0.0f;' 'hits[lane].b1 = on ? out.b2[lane] : 0.0f;' \
    rt_tests $(unit 'ItemBuffer.*:ScenePackets.*')
mutant objects-around-half-the-lanes core/item_buffer_step.cpp \
    'return op(v, __builtin_shufflevector(v, v, 1, 0, 3, 2, 5, 4, 7, 6));' 'return v;' \
    rt_tests $(unit 'ItemBuffer.*')
mutant tile-rays-off-centre core/tile_rays.h \
    'camera.across(static_cast<float>(x) + 0.5f)' 'camera.across(static_cast<float>(x) + 0.49f)' \
    rt_tests $(unit 'Render.EveryPixelIsItsCentresRayTracedAlone')
mutant tile-rays-origin-plus-zero core/tile_rays.h \
    'const Chunk v{row.x, row.y, row.z, -0.0f, -0.0f, -0.0f, -0.0f, -0.0f};' \
    'const Chunk v{row.x, row.y, row.z, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f};' \
    rt_tests $(unit 'Render.ATilesRaysAreTheCamerasRaysBitForBit')
mutant tile-rays-block-shuffled core/tile_rays.h \
    '__builtin_shufflevector(v, v, 3, 0, 1, 2, 3, 3, 3, 0),' \
    '__builtin_shufflevector(v, v, 3, 0, 2, 1, 3, 3, 3, 0),' \
    rt_tests $(unit 'Render.ATilesRaysAreTheCamerasRaysBitForBit')
mutant tile-rays-remainder-left-out core/tile_rays.h \
    'for (std::size_t k = 4 * whole; k < n; ++k)' \
    'for (std::size_t k = 4 * whole + 1; k < n; ++k)' \
    rt_tests $(unit 'Render.ATilesRaysAreTheCamerasRaysBitForBit')
mutant tile-rays-span-starts-at-the-row core/tile_rays.h \
    'reinterpret_cast<const Chunk*>(terms_->row_start(x));' \
    'reinterpret_cast<const Chunk*>(terms_->row_start(0));' \
    rt_tests $(unit 'Render.ATilesRaysAreTheCamerasRaysBitForBit')
mutant tile-rays-span-from-the-images-edge core/tile_rays.h \
    'write_run(terms_->row(t_.y0 + static_cast<int>(row)), t_.x0 + static_cast<int>(column),' \
    'write_run(terms_->row(t_.y0 + static_cast<int>(row)), static_cast<int>(column),' \
    rt_tests $(unit 'Render.ATilesRaysAreTheCamerasRaysBitForBit')
mutant tile-rays-lanes-from-the-tiles-column core/tile_rays.h \
    'std::memcpy(&c, terms_->columns_along(a, x), sizeof c);' \
    'std::memcpy(&c, terms_->columns_along(a, x - t_.x0), sizeof c);' \
    rt_tests $(unit 'ItemBuffer.*')
mutant tile-rays-span-stays-in-its-row core/tile_rays.h \
    '            column = 0;
            ++row;' '            column = 0;' \
    rt_tests $(unit 'Render.ATilesRaysAreTheCamerasRaysBitForBit')
# A tile's first sample is written to its pixels, the others added (core/renderer.cpp).
mutant every-sample-written-over-the-last core/renderer.cpp \
    'if (s == 0)' 'if (s >= 0)' \
    rt_tests $(unit 'Sampling.*')
mutant tile-rays-shading-ray-of-the-next-row core/renderer.cpp \
    'found_rays[n] = rays.ray(x, y);' 'found_rays[n] = rays.ray(x, std::min(y + 1, t.y1 - 1));' \
    rt_tests $(unit 'Render.EveryPixelIsItsCentresRayTracedAlone')
mutant packet-interval-takes-one-inverse core/wide_bvh_packet.h \
    'return d * (d >= zero ? inv_lo[a] : inv_hi[a]);' 'return d * inv_hi[a];' \
    rt_tests $(unit 'EveryKind/PacketTest.*')
mutant box-exit-without-ize-factor core/wide_bvh.h \
    'inv_far[a] = splat<Float>(inv_a * kSlabExitFactor);' 'inv_far[a] = splat<Float>(inv_a);' \
    rt_tests $(unit 'Watertight.*')
mutant packet-exit-without-ize-factor core/wide_bvh_packet.h \
    'exit_inv_hi[a] = splat<Float>(i_hi * kSlabExitFactor);' \
    'exit_inv_hi[a] = splat<Float>(i_hi);' \
    rt_tests $(unit 'Watertight.*')
mutant packet-exit-lo-without-ize-factor core/wide_bvh_packet.h \
    'exit_inv_lo[a] = splat<Float>(i_lo * kSlabExitFactor);' \
    'exit_inv_lo[a] = splat<Float>(i_lo);' \
    rt_tests $(unit 'Watertight.*')
mutant packet-ray-exit-without-ize-factor core/wide_bvh_packet.h \
    'inv_far[a] = inv[a] * kSlabExitFactor;' 'inv_far[a] = inv[a];' \
    rt_tests $(unit 'Watertight.*')
mutant packet-leaf-across-drops-a-feeler core/mesh_packet.cpp \
    'hit |= h;' 'hit |= h & (h - 1);' \
    rt_tests $(unit 'EveryKind/PacketTest.*')
mutant packet-leaf-across-swaps-barycentrics core/mesh_packet.cpp \
    'record(ray, start + k, lane[ray], b1[ray], b2[ray]);' \
    'record(ray, start + k, lane[ray], b2[ray], b1[ray]);' \
    rt_tests $(unit 'EveryKind/PacketTest.*')
mutant packet-alone-drops-a-ray core/mesh_packet.cpp \
    'if (intersect(rays[lane], hits[lane])) alone |= 1u << lane;' \
    'if (intersect(rays[lane], hits[lane])) alone |= 0u;' \
    rt_tests $(unit 'EveryKind/PacketTest.*')
mutant packet-alone-feeler-unbounded core/mesh_packet.cpp \
    'if (occluded(rays[lane], t_max[lane])) blocked |= 1u << lane;' \
    'if (occluded(rays[lane], kInfinity)) blocked |= 1u << lane;' \
    rt_tests $(unit 'EveryKind/PacketTest.*')
mutant packet-alone-none-traced core/wide_bvh_packet.h \
    'if (!boxes.set(rays, active)) return alone(active);' \
    'if (!boxes.set(rays, active)) return alone(active & (active - 1));' \
    rt_tests $(unit 'EveryKind/PacketTest.*')
mutant lazy-shear-never-set-up core/mesh.cpp \
    'bool ready_ = false;' 'bool ready_ = true;' \
    rt_tests $(unit 'EveryKind/PacketTest.*:Mesh*.*')
mutant watertight-back-faces-missed core/triangle4.h \
    '(lanes<kLe>(o.u, zero) & lanes<kLe>(o.v, zero) & lanes<kLe>(o.w, zero));' \
    '0u;' rt_tests $(unit 'Triangle4.*:TrianglePacket.*:EveryKind/PacketTest.*')
mutant watertight-error-bound-ignored core/triangle4.h \
    'return candidates & lanes<kGt>(vabs(t_scaled), t_det_error(o, abs_sz));' \
    'return candidates;' rt_tests $(unit 'Triangle4.*:TrianglePacket.*')
mutant packet-triangles-error-bound-unscaled core/triangle_packet.h \
    'watertight_hits(o, r.sz, r.abs_sz, limit, lanes, t)' \
    'watertight_hits(o, r.sz, splat<Float>(1.0f), limit, lanes, t)' \
    rt_tests $(unit 'TrianglePacket.*')
mutant packet-interval-of-the-first-ray core/ray_lanes.h \
    'const Ray& r = rays[(lanes >> k) & 1u ? k : first];' 'const Ray& r = rays[first];' \
    rt_tests $(unit 'EveryKind/PacketTest.*')
mutant packet-limit-from-lane-zero core/wide_bvh_packet.h \
    'largest = hmax(lanes);' 'largest = lanes[0];' \
    rt_tests $(unit 'EveryKind/PacketTest.*')
mutant lanes-smallest-one-step core/simd.h \
    'return vmin(v, __builtin_shufflevector(v, v, 1, 0, 3, 2))[0];' 'return v[0];' \
    rt_tests $(unit 'Simd.*:EveryKind/PacketTest.*')
mutant packet-skips-a-child core/wide_bvh_packet.h \
    'for (mask &= mask - 1; mask != 0; mask &= mask - 1) {' \
    'for (mask &= mask - 1, mask &= mask - 1; mask != 0; mask &= mask - 1) {' \
    rt_tests $(unit 'EveryKind/PacketTest.*:ScenePackets.*')
# A node that at most two rays reach is tested by each of them over all its children.
mutant packet-few-rays-child-kept-for-one core/wide_bvh_packet.h \
    'rays_in |= ((static_cast<int>(enters) & child_bit) != 0) & (1 << r);' \
    'rays_in = ((static_cast<int>(enters) & child_bit) != 0) & (1 << r);' \
    rt_tests $(unit 'EveryKind/PacketTest.*:PacketWalk.*')
mutant packet-few-rays-limit-of-the-first core/wide_bvh_packet.h \
    'const unsigned enters = boxes.ray_enters(n, r, limits.lanes[r], t);' \
    'const unsigned enters = boxes.ray_enters(n, r, limits.lanes[__builtin_ctz(rays)], t);' \
    rt_tests $(unit 'EveryKind/PacketTest.*:PacketWalk.*')
mutant packet-few-rays-entry-of-the-last core/wide_bvh_packet.h \
    't_enter = select_bits(enters, vmin(t_enter, t), t_enter);' \
    't_enter = select_bits(enters, t, t_enter);' \
    rt_tests $(unit 'PacketWalk.*')
mutant packet-few-rays-origin-of-the-first core/wide_bvh_packet.h \
    'return (n.bounds[index] - splat<Float>(origin[a][r])) * splat<Float>(inverse[a][r]);' \
    'return (n.bounds[index] - splat<Float>(origin[a][0])) * splat<Float>(inverse[a][r]);' \
    rt_tests $(unit 'EveryKind/PacketTest.*:PacketWalk.*')
# A leaf's any-hit test for feelers (TriangleMesh::leaf_blocks).
mutant leaf-blocks-first-pack-only core/mesh.h \
    'return rt::occludes(packs_[start], packs_[start + 1], r, t_max);' \
    'return rt::occludes(packs_[start], r, t_max);' \
    rt_tests $(unit '*AccelTest.*')
mutant leaf-blocks-lanes-misread core/triangle4.h \
    'return detail::any_in_lanes<Float4>(rel, r, t_max, 0xfu);' \
    'return detail::any_in_lanes<Float4>(rel, r, t_max, 0x7u);' \
    rt_tests $(unit '*AccelTest.*')
mutant corner-normals-search-merges-directions core/mesh.cpp \
    'if (dirs[d].unit == u) return d;' 'if (glm::dot(dirs[d].unit, u) > 0.5f) return d;' \
    rt_tests $(unit 'Obj.*')
mutant plane-packet-ignores-the-limit core/scene.cpp \
    '(t > zero) & (t < t_max)' '(t > zero)' \
    rt_tests $(unit 'ScenePackets.*')
mutant root-any-hit-skips-lane-0 core/wide_bvh.h \
    'mask = box_ray.test(root, t_max, t_enter); mask != 0' \
    'mask = box_ray.test(root, t_max, t_enter) & ~1u; mask != 0' \
    rt_tests $(unit '*SmallScenesOccludeAsTestingEveryObject*')
# The light buffer (core/light_buffer.h) and the feelers that skip the surface they leave.
mutant light-buffer-face-sign core/light_buffer.h \
    'w = ax, u = y, v = z, face = x < 0.0f ? 1 : 0;' 'w = ax, u = y, v = z, face = x < 0.0f ? 0 : 1;' \
    rt_tests $(unit 'LightBuffer.*:ShadowFeelers.*')
mutant light-buffer-grid-shifted core/light_buffer.cpp \
    '(glm::dot(origin, e1_) - grid_lo_f_.x)' '(glm::dot(origin, e1_) + grid_lo_f_.x)' \
    rt_tests $(unit 'LightBuffer.*')
mutant light-buffer-box-across-the-lights-plane-unclipped core/light_buffer.cpp \
    'std::max(s > 0.0 ? lo[m] : -hi[m], 1e-300)' '(s > 0.0 ? lo[m] : -hi[m])' \
    rt_tests $(unit 'LightBuffer.*')
mutant light-buffer-no-margin core/light_buffer.cpp \
    'constexpr double kMargin = 1e-5;' 'constexpr double kMargin = 0.0;' \
    rt_tests $(unit 'LightBuffer.*')
mutant crowded-cell-blocks-nothing core/scene_feelers.cpp \
    'return bounded_[slot] != leaving && occluded_by(bounded_[slot], feeler, t_limit);' \
    'return false && occluded_by(bounded_[slot], feeler, t_limit);' \
    rt_tests $(unit 'ShadowFeelers.*')
# Feelers to one light several at a time (Scene::occluded_packet, LightBuffer::cells,
# Tracer::visible_lanes).
mutant light-buffer-lanes-u-for-v core/light_buffer.cpp \
    'index(v)) * splat<Float>(kCells) + index(u);' 'index(u)) * splat<Float>(kCells) + index(v);' \
    rt_tests $(unit 'LightBuffer.*')
mutant light-buffer-lanes-face-sign core/light_buffer.cpp \
    '(along < splat<Float>(0.0f) ?' '(along > splat<Float>(0.0f) ?' \
    rt_tests $(unit 'LightBuffer.*')
mutant light-buffer-lanes-ties-to-y core/light_buffer.cpp \
    'const auto on_x = (ax >= ay) & (ax >= az);' 'const auto on_x = (ax > ay) & (ax >= az);' \
    rt_tests $(unit 'LightBuffer.*')
mutant surface-leaves-meeting-again-as-it-was core/scene.cpp \
    'sp.cannot_meet_again = leaves ? hit.object : kNoObject;' \
    'if (leaves) sp.cannot_meet_again = hit.object;' \
    rt_tests $(unit 'Scene.*')
mutant bounce-lanes-internal-reflection-in-the-reflections-place core/tracer_lanes.cpp \
    'if (next[j].bounce == Bounce::kReflection)' 'if (next[j].bounce != Bounce::kRefraction)' \
    rt_tests $(unit 'ShadeFound.*')
mutant bounce-lanes-misses-black core/tracer_lanes.cpp \
    '!= 0 ? colours[c++] : scene_.background);' '!= 0 ? colours[c++] : vec3(0.0f));' \
    rt_tests $(unit 'ShadeFound.*')
mutant bounce-lanes-hits-take-the-lanes-colour core/tracer_lanes.cpp \
    '!= 0 ? colours[c++] : scene_.background);' '!= 0 ? colours[j] : scene_.background);' \
    rt_tests $(unit 'ShadeFound.*')
mutant bounce-lanes-refraction-keeps-the-media core/tracer_lanes.cpp \
    'path.media.cross(object, m.ior).after,' 'path.media,' \
    rt_tests $(unit 'ShadeFound.*')
mutant bounce-lanes-reflection-no-deeper core/tracer_lanes.cpp \
    'return Path{path.depth + 1, path.weight * m.reflectivity, path.media,' \
    'return Path{path.depth, path.weight * m.reflectivity, path.media,' \
    rt_tests $(unit 'ShadeFound.*')
mutant bounce-lanes-found-paths-of-the-first core/tracer_lanes.cpp \
    'found_paths[j] = path_at(first + j);' 'found_paths[j] = path_at(first);' \
    rt_tests $(unit 'ShadeFound.*')
mutant few-objects-but-the-last core/scene.cpp \
    'return found | intersect_among(bounded_.data(), static_cast<int>(bounded_.size()),' \
    'return found | intersect_among(bounded_.data(), static_cast<int>(bounded_.size()) - 1,' \
    rt_tests $(unit 'ScenePackets.*')
mutant top-tree-lanes-take-no-bound core/scene.cpp \
    'hit |= intersect_primitive_packet(object, nullptr, *as_lanes, hits, lanes);' \
    'hit |= intersect_primitive_packet(object, nullptr, *as_lanes, hits, lanes, true);' \
    rt_tests $(unit 'ScenePackets.*')
mutant top-tree-lanes-of-the-first-ray core/scene.cpp \
    'as_lanes = RayLanes<kPacketWidth>::gather(rays, active);' \
    'as_lanes = RayLanes<kPacketWidth>::gather(rays, active & -active);' \
    rt_tests $(unit 'ScenePackets.*')
mutant feeler-packet-one-cell-for-all core/scene_feelers.cpp \
    'cells[k].begin == cell.begin && cells[k].end == cell.end)' 'true)' \
    rt_tests $(unit 'ShadowFeelers.*')
mutant feeler-packet-tests-only-the-left-surface core/scene_feelers.cpp \
    'if (leaving[__builtin_ctz(open)] != object)' 'if (leaving[__builtin_ctz(open)] == object)' \
    rt_tests $(unit 'ShadowFeelers.*')
mutant feeler-packet-skips-the-planes core/scene_feelers.cpp \
    'blocked |= occluded_by_packet(i, feelers, t_max, lanes);' '(void)lanes;' \
    rt_tests $(unit 'ShadowFeelers.*')
mutant feeler-packet-shape-lanes-unmoved core/scene_feelers.cpp \
    'if (!o.transform) return world;' 'return world;' \
    rt_tests $(unit 'ShadowFeelers.*')
mutant feeler-packet-mesh-drops-a-feeler core/scene_feelers.cpp \
    'return mesh.occluded_packet(rays.data(), t_max, lanes);' \
    'return mesh.occluded_packet(rays.data(), t_max, lanes & (lanes - 1));' \
    rt_tests $(unit 'ShadowFeelers.*')
mutant feeler-packet-mesh-as-a-shape core/scene_feelers.cpp \
    'return mesh ? mesh_occluded(o, meshes[mesh->mesh], feelers, t_max, lanes)' \
    'return false ? mesh_occluded(o, meshes[mesh->mesh], feelers, t_max, lanes)' \
    rt_tests $(unit 'ShadowFeelers.*')
mutant feeler-packet-shape-lanes-unbounded core/scene_feelers.cpp \
    'out.t_max[__builtin_ctz(rest)] = t_max[__builtin_ctz(rest)];' \
    'out.t_max[__builtin_ctz(rest)] = kInfinity;' \
    rt_tests $(unit 'ShadowFeelers.*')
mutant feeler-lanes-offset-ignores-sign core/vec3_lanes.h \
    '(x < splat<Float>(0.0f) ? -ulps : ulps)' 'ulps' \
    rt_tests $(unit 'ShadeFound.*')
mutant feeler-lanes-behind-origin-always-seen core/tracer.cpp \
    'bits(dot(towards, in.geometric) > splat<Float>(0.0f))' '~0u' \
    rt_tests $(unit 'ShadeFound.*')
mutant feeler-lanes-leaving-nothing core/tracer.cpp \
    'leaving[k] = sps[k].cannot_meet_again;' 'leaving[k] = kNoObject;' \
    rt_tests $(unit 'ShadeFound.*')
mutant feeler-leaving-nothing core/tracer.cpp \
    'scene_.occluded(feeler, t_max, index, sp.cannot_meet_again);' \
    'scene_.occluded(feeler, t_max, index, kNoObject);' \
    rt_tests $(unit 'ShadeFound.*')
mutant feeler-skips-a-sphere-seen-from-inside core/scene.cpp \
    '(convex == Convex::kOutside && front_face)' '(convex == Convex::kOutside)' \
    rt_tests $(unit 'ShadowFeelers.*')
mutant packet-mesh-sees-world-rays core/scene.cpp \
    'intersect_packet(local.data(), hits, lanes)' 'intersect_packet(rays, hits, lanes)' \
    rt_tests $(unit 'ScenePackets.*')
mutant item-buffer-interior-misses-the-one-above core/item_buffer.h \
    '(at[-width] ^ id) | (at[width] ^ id)) >>' '(at[-width] ^ id)) >>' \
    rt_tests $(unit 'ItemBuffer.Interior*')
mutant item-buffer-packet-lanes-unmasked core/mesh_packet.cpp \
    '1u << (at % kTriangle4Lanes));' '0xfu);' \
    rt_tests $(unit 'ScenePackets.*')
mutant sphere-lanes-take-the-near-root-only core/shape_packets.h \
    'out.t = near ? t1 : t2;' 'out.t = t1;' \
    rt_tests $(unit 'ShapeLanes.*')
mutant triangle-lanes-edge-dropped core/shape_packets.h \
    '(edge_ab < zero) | (edge_bc < zero) | (edge_ca < zero)' '(edge_ab < zero) | (edge_bc < zero)' \
    rt_tests $(unit 'ShapeLanes.*')
mutant ray-lanes-lose-the-translation core/ray_lanes.h \
    '(m[2][row] * v[2] + m[3][row] * w)' '(m[2][row] * v[2])' \
    rt_tests $(unit 'RayLanes.*')
mutant interior-run-sees-no-side-neighbour core/item_buffer.h \
    'const Ids differ = ((load(centre - 1) ^ id) | (load(centre + 1) ^ id) |' \
    'const Ids differ = ((load(centre + 1) ^ id) |' \
    rt_tests $(unit 'ItemBuffer.*')
mutant item-buffer-run-never-falls-back core/item_buffer_step.cpp \
    'const unsigned open = all & ~settled;' 'const unsigned open = 0;' \
    rt_tests $(unit 'ItemBuffer.*')
mutant inside-run-never-falls-back core/item_buffer_step.cpp \
    'if (found != kAll)' 'if (false)' \
    rt_tests $(unit 'ItemBuffer.*')
mutant inside-run-takes-a-run-with-an-edge core/item_buffer_step.cpp \
    'if (interior == kAll && n == kPacketWidth && tiny.lanes == 0) {' \
    'if (n == kPacketWidth && tiny.lanes == 0) {' \
    rt_tests $(unit 'ItemBuffer.*')
mutant background-run-keeps-old-hits core/item_buffer_step.cpp \
    'reset_hits(&hits[i], kPacketWidth);  // the background, and only it around' ';' \
    rt_tests $(unit 'ItemBuffer.*')
mutant edge-pixels-look-along-their-row-only core/item_buffer_step.cpp \
    'const int row = y - 1 + d;' \
    'const int row = y;' \
    rt_tests $(unit 'ItemBuffer.*')
mutant objects-around-drop-the-right-neighbours core/item_buffer_step.cpp \
    'ids[2 * d + 1] = (ib.object_ids(at + kPacketWidth) & in_span[1]) - 1u;' \
    'ids[2 * d + 1] = (ib.object_ids(at + kPacketWidth) & Ids{}) - 1u;' \
    rt_tests $(unit 'ItemBuffer.*')
mutant objects-around-two-where-there-are-more core/item_buffer_step.cpp \
    'if (bits(others != Ids{}) == 0) {' 'if (true) {' \
    rt_tests $(unit 'ItemBuffer.*')
mutant objects-around-one-where-there-are-two core/item_buffer_step.cpp \
    'if (hi == lo) return 1;' 'return 1;' \
    rt_tests $(unit 'ItemBuffer.*')
mutant objects-around-first-found-not-cleared core/item_buffer_step.cpp \
    'for (Ids& v : ids) v |= Ids(v == m);  // m is the least in every lane' \
    'for (Ids& v : ids) v |= Ids(v == m) & Ids{};' \
    rt_tests timeout 60 $(unit 'ItemBuffer.*')
mutant per-lane-triangles-all-named-the-first core/mesh_packet.cpp \
    'hits[ray].prim = prims[ray];' 'hits[ray].prim = first;' \
    rt_tests $(unit 'ScenePackets.*')
mutant packed-ids-read-as-objects core/item_buffer.h \
    'Ids object_ids(std::size_t i) const { return load(&ids[i]) >> prim_bits; }' \
    'Ids object_ids(std::size_t i) const { return load(&ids[i]); }' \
    rt_tests timeout 60 $(unit 'ItemBuffer.ARunsCheckIsEachPixelsOwn')
mutant packed-ids-interior-sees-triangles core/item_buffer.h \
    '(load(centre - w) ^ id) | (load(centre + w) ^ id)) >>
                                   prim_bits;' \
    '(load(centre - w) ^ id) | (load(centre + w) ^ id)) >>
                                   0;' \
    rt_tests $(unit 'ItemBuffer.ARunsCheckIsEachPixelsOwn')
mutant packed-ids-triangles-keep-the-object core/item_buffer.h \
    'const Ids t = prim.empty() ? load(&ids[i]) & prim_mask() : load(&prim[i]);' \
    'const Ids t = prim.empty() ? load(&ids[i]) : load(&prim[i]);' \
    rt_tests $(unit 'ItemBuffer.AFrameFromAPerfectItemBufferIsTheFrameFromScratch')
mutant packed-ids-read-back-unshifted app/gl/framebuffer.cpp \
    'ib.resize(fb_.width_, fb_.height_, static_cast<int>(layout.shader_prim_bits()),' \
    'ib.resize(fb_.width_, fb_.height_, 0,' \
    rt_gl_tests "${gl[@]}" --gtest_filter='*TriangleOfAMesh*:*PackedIds*:*SameItemBuffer*'
mutant ids-read-straight-leave-the-triangles app/gl/framebuffer.cpp \
    'fb_.read_ids(ib.ids.data(), ib.prim.data());' 'fb_.read_ids(ib.ids.data(), ib.ids.data());' \
    rt_gl_tests "${gl[@]}" --gtest_filter='*IdsReadStraight*'
mutant item-buffer-read-into-storage-keeps-its-height core/item_buffer.h \
    'width = w, height = h, prim_bits = bits;' 'width = w, prim_bits = bits;' \
    rt_gl_tests "${gl[@]}" --gtest_filter='*EarlierFrame*'
mutant triangle-ids-never-drawn app/gl/framebuffer.cpp \
    'if (most_triangles == 0) return {Kind::kObjectsOnly, 0};' 'return {Kind::kObjectsOnly, 0};' \
    rt_gl_tests "${gl[@]}" --gtest_filter='*TriangleOfAMesh*:*PacksWhere*'
mutant triangle-ids-packed-past-their-bits app/gl/framebuffer.cpp \
    'most_triangles <= (std::uint64_t{1} << prim_bits)' 'most_triangles <= (std::uint64_t{2} << prim_bits)' \
    rt_gl_tests "${gl[@]}" --gtest_filter='*TriangleOfAMesh*:*PacksWhere*:*PackedIds*'
mutant triangle-ids-read-though-not-drawn app/gl/framebuffer.cpp \
    'for (int k = 0; k < (ids_.second_target() ? 2 : 1); ++k) {' 'for (int k = 0; k < 2; ++k) {' \
    rt_gl_tests "${gl[@]}" --gtest_filter='*TriangleOfAMesh*:*SameItemBuffer*:*PackedIds*'
# An edge's list of objects (Scene::intersect_among): the closest hits kept as lanes.
mutant item-buffer-edges-take-their-hits-as-fresh core/shape_packets.h \
    'c.t = t_bounds<kPacketWidth>(hits, lanes);' 'c.t = splat<Float>(kInfinity);' \
    rt_tests $(unit 'ItemBuffer.*:ScenePackets.*')
mutant among-object-not-taken core/shape_packets.h \
    'object = select_bits(hit, splat<Float>(std::bit_cast<float>(id)), object);' \
    'object = splat<Float>(std::bit_cast<float>(id));' \
    rt_tests $(unit 'ScenePackets.*')
mutant among-barycentrics-swapped core/shape_packets.h \
    'b1 = select_bits(hit, out.b1, b1);' 'b1 = select_bits(hit, out.b2, b1);' \
    rt_tests $(unit 'ScenePackets.*')
mutant among-mesh-before-the-shapes-written core/scene.cpp \
    'if (open) best.write(hits), open = false;' 'if (open) open = false;' \
    rt_tests $(unit 'ScenePackets.*')
mutant among-shapes-after-a-mesh-keep-old-bounds core/scene.cpp \
    'if (open) best.write(hits), open = false;' 'if (open) best.write(hits);' \
    rt_tests $(unit 'ScenePackets.*')
mutant among-mesh-rays-of-the-first-lane core/scene.cpp \
    'as_rays[__builtin_ctz(rest)] = rays.lane(__builtin_ctz(rest));' \
    'as_rays[__builtin_ctz(rest)] = rays.lane(__builtin_ctz(lanes));' \
    rt_tests $(unit 'ScenePackets.*')
mutant item-buffer-fresh-hit-keeps-no-object core/scene.cpp \
    '            hits[lane].object = object;' '' \
    rt_tests $(unit 'ItemBuffer.*:ScenePackets.*')
mutant ply-binary-vertex-index-unchecked core/ply_check.cpp \
    'if (index < 0 || static_cast<std::uint64_t>(index) >= h.vertices)' 'if (index < 0)' \
    rt_tests $(unit 'PlyStl.*')
mutant ply-ascii-vertex-index-off-by-one core/ply_check.cpp \
    '                        static_cast<std::uint64_t>(index) >= h.vertices)' \
    '                        static_cast<std::uint64_t>(index) > h.vertices)' \
    rt_tests $(unit 'PlyStl.*')
mutant ply-header-unchecked core/assimp_loader.cpp \
    '        check_ply(file, in, std::filesystem::file_size(path, ec));' '' \
    rt_tests timeout 60 $(unit 'PlyStl.*')
mutant ply-faces-without-vertices-triangulated core/assimp_loader.cpp \
    'if (face.mNumIndices == 0) {' 'if (false) {' \
    rt_tests $(unit 'PlyStl.*')
mutant ply-primitive-types-not-recounted core/assimp_loader.cpp \
    'mesh.mPrimitiveTypes = types;' '' \
    rt_tests $(unit 'PlyStl.*')
mutant ply-counts-unchecked core/ply_check.cpp \
    'if (e.count > budget / least)' 'if (false)' \
    rt_tests timeout 60 $(unit 'PlyStl.*')
mutant ply-byte-order-mark-kept core/assimp_loader.cpp \
    'return std::string(mark, 3) + all.str();' 'return {};' \
    rt_tests $(unit 'PlyStl.*')
mutant small-scene-far-out-not-rebased core/scene_loader_shared.h \
    'constexpr double kFarForItsSize = 256.0;' 'constexpr double kFarForItsSize = 1e300;' \
    rt_tests $(unit 'Far.*')
mutant collapse-part-misplaced core/wide_bvh.cpp \
    'out[d.parent].child[d.lane] = d.at;' 'out[d.parent].child[d.lane] = d.at + 1;' \
    rt_tests $(unit '*TheTreeIsTheSameOnAnyNumberOfThreadsAndWhole*')
mutant collapse-cut-by-threads core/wide_bvh.cpp \
    'if (l.end[k] - l.node[k] > kPartNodes)' \
    'if (l.end[k] - l.node[k] > kPartNodes * static_cast<std::uint32_t>(threads_))' \
    rt_tests $(unit '*TheTreeIsTheSameOnAnyNumberOfThreadsAndWhole*')
mutant collapse-part-counted-short core/wide_bvh.cpp \
    'std::uint32_t total = 1;' 'std::uint32_t total = 0;' \
    rt_tests $(unit '*TheTreeIsTheSameOnAnyNumberOfThreadsAndWhole*')
mutant gpu-checker-shift-rounded shaders/gputrace.comp \
    'precise vec3 r = (x - product) - error;' 'precise vec3 r = x - product;' \
    rt_gl_tests "${gl[@]}" --gtest_filter='*GpuTrace.AgreesOnTheCorners*'

# rtbench's arbiter (app/bench/exact.cpp) and verdict (app/bench/bench_scene.cpp): the
# CLI test must notice a slack that depends on the vertex order (a false WRONG on a tube
# of slivers) and Embree's own errors failing the run.
mutant arbiter-slack-by-the-first-corner app/bench/exact.cpp \
    'h.slack = t_rounding(o, d, corner, h.t);' \
    'h.slack = kTMargin * corners * glm::length(e1) * glm::length(e2) / std::fabs(det);' \
    rtbench ctest -R '^cli[.]rtbench$' --output-on-failure
mutant arbiter-embree-errors-fail-the-run app/bench/bench_scene.cpp \
    'verdict.embree_wrong = true;' 'verdict.ok = false;' \
    rtbench ctest -R '^cli[.]rtbench$' --output-on-failure

# The POV-Ray oracle (tests/oracle) alone, without the unit tests: an independent tracer
# must notice a planted bug in refraction, shadows, the camera and transforms.
oracle=(ctest -R '^oracle[.]' --output-on-failure)
cmake --build "$build" --target rtgolden >"$scratch/rtgolden.build.log" 2>&1
mutant oracle-refraction-indices-swapped core/tracer.cpp \
    'sp.normal, crossing.eta_from, crossing.eta_to)' 'sp.normal, crossing.eta_to, crossing.eta_from)' \
    rtrender "${oracle[@]}"
mutant oracle-glass-nesting-ignored core/medium.h \
    'Crossing c{ior(), 1.0f, *this};' 'Crossing c{1.0f, 1.0f, *this};' rtrender "${oracle[@]}"
mutant oracle-shadow-feeler-dropped core/tracer.cpp \
    'const unsigned blocked =
        scene_.occluded_packet(' 'const unsigned blocked = 0 &
        scene_.occluded_packet(' \
    rtrender "${oracle[@]}"
mutant oracle-camera-fov-2-percent-wide core/camera.cpp \
    'std::tan(glm::radians(vfov_degrees) * 0.5f)' 'std::tan(glm::radians(vfov_degrees) * 0.51f)' \
    rtrender "${oracle[@]}"
mutant oracle-rotation-before-scale core/scene_loader.cpp \
    'm = glm::rotate(glm::dmat4(1.0), glm::radians(deg[axis]), unit) * m;' \
    'm = m * glm::rotate(glm::dmat4(1.0), glm::radians(deg[axis]), unit);' rtrender "${oracle[@]}"
mutant oracle-transform-normal core/transform.cpp \
    't.normal = glm::transpose(glm::inverse(linear));' 't.normal = glm::inverse(linear);' \
    rtrender "${oracle[@]}"

# Objects too small on the screen for the item buffer (core/small_objects.h): their
# pixels are taken from the ids' trust and tested against them.
mutant small-objects-pixels-still-trusted core/item_buffer_step.cpp \
    'own_ids(scene, ib, at, n, lanes, hits, interior, !whole, left) & ~tiny.lanes;' \
    'own_ids(scene, ib, at, n, lanes, hits, interior, !whole, left);' \
    rt_tests $(unit 'ItemBuffer.*')
mutant small-objects-not-tested core/item_buffer_step.cpp \
    'if (tiny.count > 0) scene.intersect_among(tiny.objects.data(), tiny.count, lanes, hits, open);' '' \
    rt_tests $(unit 'ItemBuffer.*')
mutant inside-run-under-a-small-object core/item_buffer_step.cpp \
    'if (interior == kAll && n == kPacketWidth && tiny.lanes == 0) {' \
    'if (interior == kAll && n == kPacketWidth) {' \
    rt_tests $(unit 'ItemBuffer.*')
mutant small-objects-none-small-enough core/small_objects.h \
    'static constexpr float kPixels = 6.0f;' 'static constexpr float kPixels = 1.0f;' \
    rt_tests $(unit 'ItemBuffer.*')

# Spheres cut by the image's edge: tested along it, on each side, where they reach in
# by little.
mutant edge-spheres-not-listed core/small_objects.cpp \
    'edge_patches(i, exact ? exact : b, exact.has_value(), camera, patches, sides);' '{}' \
    rt_tests $(unit 'ItemBuffer.*')
mutant edge-spheres-right-side-left-out core/small_objects.cpp \
    'if (b->x_hi > cols && b->x_lo > cols - reach) sides.push_back({object, last_x, last_x, y0, y1});' \
    '' rt_tests $(unit 'ItemBuffer.*')
mutant edge-spheres-left-side-left-out core/small_objects.cpp \
    'if (b->x_lo < 0.0f && b->x_hi < reach) sides.push_back({object, 0, 0, y0, y1});' '' \
    rt_tests $(unit 'ItemBuffer.*')
mutant edge-spheres-bottom-left-out core/small_objects.cpp \
    'if (b->y_lo < 0.0f && b->y_hi < reach) rows.push_back({object, x0, x1, 0, 0});' '' \
    rt_tests $(unit 'ItemBuffer.*')
mutant edge-spheres-top-left-out core/small_objects.cpp \
    'rows.push_back({object, x0, x1, last_y, last_y});' '{}' rt_tests $(unit 'ItemBuffer.*')
mutant edge-spheres-one-column-in core/small_objects.cpp \
    'sides.push_back({object, last_x, last_x, y0, y1});' \
    'sides.push_back({object, last_x - 1, last_x - 1, y0, y1});' rt_tests $(unit 'ItemBuffer.*')
mutant edge-spheres-reach-too-short core/small_objects.cpp \
    'const float reach = exact ? 2.0f : INFINITY;' 'const float reach = exact ? 0.5f : INFINITY;' \
    rt_tests $(unit 'ItemBuffer.*')
mutant edge-spheres-box-too-narrow core/small_objects.cpp \
    'const double t_lo = (across * z - root) / k, t_hi = (across * z + root) / k;' \
    'const double t_lo = (across * z - 0.5 * root) / k, t_hi = (across * z + 0.5 * root) / k;' \
    rt_tests $(unit 'ItemBuffer.*')
# The raster's sphere of a sphere millions of pixels wide (core/tessellate.cpp).
mutant sphere-segments-cast-unclamped core/tessellate.cpp \
    'return static_cast<int>(std::ceil(std::clamp(n, 12.0f, 256.0f)));' \
    'return std::clamp(static_cast<int>(std::ceil(n)), 12, 256);' \
    rt_tests $(unit 'Far.ASphereThatLooksMillionsOfPixelsWideGetsTheFinestMesh')
# A box projected from just in front of the eye's plane (ItemBuffer.ASphereSeenFromJust...).
mutant small-objects-span-unclamped core/small_objects.cpp \
    'std::ceil(std::clamp(lo - 0.5f, below, above))' 'std::ceil(lo - 0.5f)' \
    rt_tests $(unit 'ItemBuffer.*')
mutant edge-spheres-right-side-not-read core/item_buffer_step.cpp \
    'if (x == 0 || x + n == width) take(small.side(y));' 'if (x == 0) take(small.side(y));' \
    rt_tests $(unit 'ItemBuffer.*')

# A build's large arrays (core/large_array.cpp): on huge-page boundaries, kept when freed,
# within a bound, and only for an array of about their size.
mutant large-array-not-aligned core/large_array.cpp \
    'char* const start = base + (kHugePageBytes - at % kHugePageBytes) % kHugePageBytes;' \
    'char* const start = base + (at % kHugePageBytes == 0 ? kHugePageBytes / 2 : 0);' \
    rt_tests $(unit 'LargeArray.*')
mutant large-array-never-kept core/large_array.cpp \
    'if (kept_ + size <= kKeptBytes) {' 'if (false) {' rt_tests $(unit 'LargeArray.*')
mutant large-array-kept-unbounded core/large_array.cpp \
    'kKeptBytes = std::size_t{256} << 20;' 'kKeptBytes = ~std::size_t{0} >> 1;' \
    rt_tests $(unit 'LargeArray.*')
mutant large-array-kept-block-of-any-size core/large_array.cpp \
    'blocks_[i].size >= size && blocks_[i].size <= 2 * size &&' 'blocks_[i].size >= size &&' \
    rt_tests $(unit 'LargeArray.*')

# Long thin triangles cut in pieces (core/triangle_refs.h): the pieces cover their
# triangle (the edges' crossings of the cuts, bounds rounded outwards), each names its
# triangle, and thin large triangles are cut at all.
mutant thin-pieces-without-edge-crossings core/triangle_refs.cpp \
    'for (int i = 1; i < pieces; ++i) cut_edges(' 'for (int i = 1; i < 1; ++i) cut_edges(' \
    rt_tests $(unit 'TriangleRefs.*')
mutant thin-pieces-rounded-to-nearest core/triangle_refs.cpp \
    'return f - (std::abs(f) * 0x1p-21f + std::numeric_limits<float>::min());' 'return f;' \
    rt_tests $(unit 'TriangleRefs.*')
mutant thin-pieces-name-one-triangle core/triangle_refs.h \
    'return ref < n ? ref : extra_triangles[ref - n];' 'return ref < n ? ref : extra_triangles[0];' \
    rt_tests $(unit 'TriangleRefs.*')
mutant thin-pieces-packed-as-one-triangle core/mesh.cpp \
    'ref < n ? ref : extra[ref - n];' 'ref < n ? ref : extra[0];' \
    rt_tests $(unit 'TriangleRefs.*')
mutant thin-triangles-never-cut core/triangle_refs.cpp \
    'if (!(largest > large)) return refs;' 'return refs;' rt_tests $(unit 'TriangleRefs.*')

echo "$caught caught, $missed missed, $broken could not be planted"
[ "$missed" -gt 0 ] && echo "missed: ${missed_names[*]}"
[ "$missed" -eq 0 ] && [ "$broken" -eq 0 ]
