// essi_gen_batch DIR COUNT [MIN_KB MAX_KB]: writes COUNT generated nesting tapes (tests/bench/nest_generator.hpp)
// of MIN_KB..MAX_KB kilobytes (default 20..50, sizes spread evenly, seed = index) into DIR/NNN/tNNNNN.esi
// (100 files a folder). Used by scripts/bench_batch for `essi check --jobs N DIR`.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "../nest_generator.hpp"

int main(int argc, char** argv) {
    if (argc < 3) {
        std::fprintf(stderr, "usage: essi_gen_batch DIR COUNT [MIN_KB MAX_KB]\n");
        return 2;
    }
    const std::filesystem::path dir = argv[1];
    const long count = std::strtol(argv[2], nullptr, 10);
    const double min_kb = argc > 3 ? std::strtod(argv[3], nullptr) : 20;
    const double max_kb = argc > 4 ? std::strtod(argv[4], nullptr) : 50;
    if (count <= 0 || !(min_kb > 0) || max_kb < min_kb) {
        std::fprintf(stderr, "essi_gen_batch: bad COUNT or sizes\n");
        return 2;
    }
    unsigned long long total = 0;
    for (long i = 0; i < count; ++i) {
        const double kb = min_kb + (max_kb - min_kb) * static_cast<double>(i % 97) / 96.0;
        const std::string tape =
            essi::bench::generate_nest_tape(static_cast<std::size_t>(kb * 1000), static_cast<unsigned>(i + 1));
        char sub[32], name[32];
        std::snprintf(sub, sizeof sub, "%03ld", i / 100);
        std::snprintf(name, sizeof name, "t%05ld.esi", i);
        std::filesystem::create_directories(dir / sub);
        const std::string path = (dir / sub / name).string();
        std::FILE* f = std::fopen(path.c_str(), "wb");
        if (!f || std::fwrite(tape.data(), 1, tape.size(), f) != tape.size() || std::fclose(f) != 0) {
            std::perror(path.c_str());
            return 1;
        }
        total += tape.size();
    }
    std::printf("%ld tapes, %.1f MB, in %s\n", count, static_cast<double>(total) / 1e6, dir.string().c_str());
    return 0;
}
