// rt_soak: loads, builds, renders and drops every shipped scene ITERATIONS times in one
// process, and fails if the memory still allocated (malloc's live bytes, every arena)
// grew by more than a bound between the end of the first round (caches warm) and the end
// of the last. Resident memory is printed too, but it is not the test: how the allocator
// keeps freed pages depends on the machine (a many-core CI machine grew 18 MiB resident
// with nothing leaked), while a leak of even 10 KiB a round shows in the live bytes.
//   rt_soak SCENES_DIR [ITERATIONS=100] [BOUND_MIB=1]
#include <malloc.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <vector>

#include "core/error.h"
#include "core/renderer.h"
#include "core/scene_loader.h"

namespace {

double resident_mib() {
    std::ifstream statm("/proc/self/statm");
    long pages_total = 0, pages_resident = 0;
    statm >> pages_total >> pages_resident;
    return static_cast<double>(pages_resident) * static_cast<double>(sysconf(_SC_PAGESIZE)) /
           (1024.0 * 1024.0);
}

// Bytes handed out by malloc and not yet freed, over all arenas and large mappings.
double live_heap_mib() {
    const struct mallinfo2 info = mallinfo2();
    return static_cast<double>(info.uordblks + info.hblkhd) / (1024.0 * 1024.0);
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: rt_soak SCENES_DIR [ITERATIONS] [BOUND_MIB]\n");
        return 2;
    }
    const int iterations = argc > 2 ? std::atoi(argv[2]) : 100;
    const double bound = argc > 3 ? std::atof(argv[3]) : 1.0;
    std::vector<std::filesystem::path> scenes;
    for (const auto& entry : std::filesystem::directory_iterator(argv[1]))
        if (entry.path().extension() == ".json") scenes.push_back(entry.path());
    std::sort(scenes.begin(), scenes.end());
    double after_first = 0.0, heap_after_first = 0.0;
    try {
        for (int i = 0; i < iterations; ++i) {
            for (const auto& path : scenes) {
                rt::LoadedScene loaded = rt::load_scene(path);
                loaded.scene.camera = loaded.scene.camera.resized(32, 24);
                const rt::Scene scene(std::move(loaded.scene));
                rt::RenderOptions options;
                options.threads = 2;
                const rt::Image image = rt::render(scene, options);
                if (image.pixels.size() != 32u * 24u) return 1;
            }
            if (i == 0) {
                after_first = resident_mib();
                heap_after_first = live_heap_mib();
            }
        }
    } catch (const rt::Error& e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 1;
    }
    const double after_last = resident_mib();
    const double heap_after_last = live_heap_mib();
    const double growth = heap_after_last - heap_after_first;
    const bool ok = growth <= bound;
    std::printf(
        "%zu scenes x %d: allocated %.2f MiB after the first round, %.2f MiB after the last "
        "(growth %.3f MiB, bound %.1f): %s; resident %.1f then %.1f MiB\n",
        scenes.size(), iterations, heap_after_first, heap_after_last, growth, bound,
        ok ? "ok" : "GREW", after_first, after_last);
    return ok ? 0 : 1;
}
