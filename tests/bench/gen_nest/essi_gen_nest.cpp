// essi_gen_nest SIZE_MB OUT [--lf] [--seed N]: writes a generated nesting tape (tests/bench/nest_generator.hpp)
// of SIZE_MB megabytes (10^6 bytes) to OUT. CR LF line ends unless --lf. Used by scripts/bench_compare.
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "../nest_generator.hpp"

int main(int argc, char** argv) {
    if (argc < 3) {
        std::fprintf(stderr, "usage: essi_gen_nest SIZE_MB OUT [--lf] [--seed N]\n");
        return 2;
    }
    const double mb = std::strtod(argv[1], nullptr);
    if (!(mb > 0)) {
        std::fprintf(stderr, "essi_gen_nest: SIZE_MB must be a positive number, got '%s'\n", argv[1]);
        return 2;
    }
    auto eol = essi::bench::LineEnding::CrLf;
    unsigned seed = 1;
    for (int i = 3; i < argc; ++i) {
        const std::string_view a = argv[i];
        if (a == "--lf") {
            eol = essi::bench::LineEnding::Lf;
        } else if (a == "--seed" && i + 1 < argc) {
            seed = static_cast<unsigned>(std::strtoul(argv[++i], nullptr, 10));
        } else {
            std::fprintf(stderr, "essi_gen_nest: unknown argument '%s'\n", argv[i]);
            return 2;
        }
    }
    const std::string tape = essi::bench::generate_nest_tape(static_cast<std::size_t>(mb * 1e6), seed, eol);
    std::FILE* f = std::fopen(argv[2], "wb");
    if (!f) {
        std::perror(argv[2]);
        return 1;
    }
    const bool ok = std::fwrite(tape.data(), 1, tape.size(), f) == tape.size();
    if (std::fclose(f) != 0 || !ok) {
        std::perror(argv[2]);
        return 1;
    }
    return 0;
}
