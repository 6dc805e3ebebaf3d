// Runs a libFuzzer harness once on every file of the folders given (its corpus and its
// regressions), as the fuzzer replays them, for builds without libFuzzer: a crash, a sanitizer
// report (in the debug preset) or an exception the harness lets through fails the test, and so
// does an input that takes more than kSeconds (a hang: the fuzzers run with -timeout=20).
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {

constexpr unsigned kSeconds = 20;
/// Names the input being run; made before it runs (the handler allocates nothing).
std::string hangMessage;

void hang(int) {
    (void)!::write(2, hangMessage.data(), hangMessage.size());
    ::_exit(70);
}

}  // namespace

int main(int argc, char** argv) {
    namespace fs = std::filesystem;
    std::size_t inputs = 0;
    ::signal(SIGALRM, hang);
    for (int a = 1; a < argc; ++a) {
        if (!fs::is_directory(argv[a])) {
            std::fprintf(stderr, "%s: not a folder of inputs\n", argv[a]);
            return 1;
        }
        std::vector<fs::path> files;
        for (const auto& e : fs::directory_iterator(argv[a]))
            if (e.is_regular_file()) files.push_back(e.path());
        std::sort(files.begin(), files.end());
        for (const fs::path& f : files) {
            std::ifstream in(f, std::ios::binary);
            const std::string bytes((std::istreambuf_iterator<char>(in)),
                                    std::istreambuf_iterator<char>());
            hangMessage = f.string() + ": more than " + std::to_string(kSeconds) + " s (a hang)\n";
            ::alarm(kSeconds);
            LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()),
                                   bytes.size());
            ::alarm(0);
            ++inputs;
        }
    }
    std::printf("%zu inputs replayed, none failed\n", inputs);
    return inputs > 0 ? 0 : 1;
}
