#include "app/app.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

#include "app/errors.hpp"
#include "app/expression.hpp"
#include "app/simulation.hpp"
#include "device/backend.hpp"
#include "run/agreed_errors.hpp"
#include "sph/scheduler.hpp"
#include "sph/settings.hpp"

namespace num::app {

namespace {

std::string examples(const std::string& name, int dim) {
    const std::string other = dim == 2 ? "hot_cold_exchange_3d.json" : "dam_break_hot_cold_2d.json";
    const std::string scene =
        dim == 2 ? "scenes/dam_break_hot_cold_2d.json" : "scenes/dam_break_3d.json";
    return "Examples:\n"
           "  " +
           name +
           "                               run the built-in default scene\n"
           "  " +
           name + " " + scene +
           "\n"
           "  " +
           name + " " + scene +
           " --out out/mine --end-time 0.5\n"
           "  " +
           name + " " + scene +
           " --set particles.spacing=0.01 --set time.cfl=0.2\n"
           "  " +
           name +
           " --threads 2 --backend omp --checkpoint-every 0.5\n"
           "  " +
           name +
           " --restart out/<dir>/checkpoint_0001.chk\n"
           "  " +
           name +
           " --print-scene > my_scene.json   start a scene of your own\n"
           "  " +
           name +
           " --list-scenes                 the shipped scenes, one line each\n"
           "Scene format and exit codes: docs/scenes.md. Outputs: a ParaView series (.pvd), PNG\n"
           "pictures, probes.csv and summary.json in the output directory.\n"
           "(" +
           other + " is a " + std::to_string(5 - dim) + "D scene: run it with " +
           (dim == 2 ? "fluid_sim_3d" : "fluid_sim") + ".)";
}

/// The first sentence of a description, on one line and at most about 110 characters.
std::string firstSentence(std::string text) {
    std::replace(text.begin(), text.end(), '\n', ' ');
    const std::size_t end = text.find(". ");
    if (end != std::string::npos) text.resize(end + 1);
    if (text.size() > 110) text = text.substr(0, 107) + "...";
    return text.empty() ? "(no description)" : text;
}

}  // namespace

int listScenes(const std::string& dir, const AppInfo& info) {
    namespace fs = std::filesystem;
    std::vector<fs::path> files;
    for (const std::string sub : {"", "validation"}) {
        std::vector<fs::path> here;
        // Without exceptions: an entry that cannot be examined (a symbolic link in a loop, one
        // to nothing, no permission) is left out, and so is the rest of a folder that cannot
        // be read on.
        std::error_code ec;
        for (fs::directory_iterator it(fs::path(dir) / sub, ec), end; !ec && it != end;
             it.increment(ec)) {
            std::error_code fileEc;
            if (it->is_regular_file(fileEc) && it->path().extension() == ".json")
                here.push_back(it->path());
        }
        std::sort(here.begin(), here.end());
        files.insert(files.end(), here.begin(), here.end());
    }
    if (files.empty()) {
        std::fprintf(stderr, "%s: error: no scene files in %s\n", info.name.c_str(), dir.c_str());
        return int(ExitCode::SCENE_FILE);
    }
    std::printf("Scenes: the command that runs each, then what it shows\n");
    for (const fs::path& f : files) {
        std::string app = "?", text;
        try {
            const SceneDocument doc = SceneDocument::fromFile(f.string());
            app = doc.json().value("dimension", 0) == 3 ? "fluid_sim_3d" : "fluid_sim";
            text = firstSentence(doc.json().value("description", std::string()));
        } catch (const std::exception& e) {
            text = std::string("(cannot be read: ") + e.what() + ")";
        }
        if (app == info.name && f.filename() == info.defaultSceneName)
            text = "[default of " + app + "] " + text;
        std::printf("  %s %s\n      %s\n", app.c_str(), f.string().c_str(), text.c_str());
    }
    std::printf("Without a scene file, %s runs its default scene.\n", info.name.c_str());
    return 0;
}

/// Under mpirun, the processes other than the root print nothing: every error they share is
/// reported by the root. Returns a descriptor of the original standard error, for an error only
/// this process meets.
int quietUnlessRoot(const parallel::Communicator& comm) {
    const int error = ::dup(STDERR_FILENO);
    if (comm.isRoot()) return error;
    if (const int null = ::open("/dev/null", O_WRONLY); null >= 0) {
        ::dup2(null, STDOUT_FILENO), ::dup2(null, STDERR_FILENO);
        ::close(null);
    }
    return error;
}

namespace {

/// What the command line asks for.
struct CommandLine {
    std::string sceneFile, out, restart;
    std::vector<std::string> sets;
    RunOptions options;
    double endTime = 0;
    bool printScene = false, list = false, version = false;
};

void addOptions(CLI::App& app, CommandLine& c, const AppInfo& info) {
    app.add_option(
        "scene", c.sceneFile,
        "scene file (JSON); without it the built-in scene " + info.defaultSceneName + " runs");
    app.add_option("--out", c.out, "output directory (default: the scene's output.directory)");
    app.add_option("--threads", c.options.threads,
                   "threads of the omp and threads backends (default: all cores)")
        ->check(CLI::Range(1, 1024));
    app.add_option("--backend", c.options.backend,
                   "seq (one thread), omp (OpenMP), threads or cpu (default: a pool of threads\n"
                   "that sleep when idle, faster than omp on a machine busy with other work), or\n"
                   "cuda (the steps on an NVIDIA GPU; needs a build with CUDA: see --version);\n"
                   "replaces the scene's numerics.backend")
        ->check(CLI::IsMember({"seq", "omp", "threads", "cpu", "cuda"}));
    // Finite and positive: CLI::PositiveNumber lets "nan" through.
    const CLI::Validator finitePositive(
        [](std::string& text) {
            double v = 0;
            return CLI::detail::lexical_cast(text, v) && std::isfinite(v) && v > 0
                       ? std::string()
                       : "a finite number > 0 is required, found " + text;
        },
        "POSITIVE");
    app.add_option("--end-time", c.endTime, "end time [s] (default: the scene's time.end)")
        ->check(finitePositive);
    app.add_option("--set", c.sets,
                   "override a scene value by its dotted path, e.g.\n"
                   "--set particles.spacing=0.01 --set fluids.0.temperature=30 "
                   "(repeatable)");
    app.add_option("--restart", c.restart, "continue from a checkpoint file");
    app.add_option("--checkpoint-every", c.options.checkpointEvery,
                   "write a checkpoint every T simulated seconds")
        ->check(finitePositive);
    app.add_flag("-q,--quiet", c.options.quiet, "print nothing but errors");
    CLI::Option* print = app.add_flag("--print-scene", c.printScene,
                                      "print the scene (after --set) as JSON and exit");
    app.add_flag("--list-scenes", c.list,
                 "list the shipped scenes (./scenes, else the source tree's) with the program that "
                 "runs each, and exit")
        ->excludes(print);
    // A plain flag, handled after parsing: "--version --bogus" is a bad command line (2), not
    // the version.
    app.add_flag("--version", c.version, "print the version and exit");
}

/// The scene to run: the file given, else the checkpoint's, else the built-in one; --set applied.
template <int Dim>
SceneDocument sceneToRun(const CommandLine& c, const AppInfo& info) {
    SceneDocument doc = !c.sceneFile.empty() ? SceneDocument::fromFile(c.sceneFile)
                        : c.options.restart
                            ? sceneOfCheckpoint(*c.options.restart, Dim)
                            : SceneDocument::fromText(info.defaultScene, info.defaultSceneName);
    for (const std::string& s : c.sets) doc.set(s);
    const int dim = doc.dimension();
    if (dim != Dim)
        throw AppError(ExitCode::SCENE,
                       doc.file() + ": dimension: this is a " + std::to_string(dim) + "D scene, " +
                           info.name + " runs " + std::to_string(Dim) + "D scenes: run it with " +
                           (dim == 2 ? "fluid_sim" : "fluid_sim_3d"));
    return doc;
}

/// Runs f and returns its exit code; an error becomes one line and its exit code. `alone`
/// reports an error this process alone met (and ends every process).
template <class F, class Alone>
int reportingErrors(const std::string& program, F&& f, Alone&& alone) {
    try {
        return f();
    } catch (const LoneFailure& e) {
        return alone(std::string("error: ") + e.what(), e.code());
    } catch (const AppError& e) {
        std::fflush(stdout);
        std::fprintf(stderr, "%s: error: %s\n", program.c_str(), e.what());
        return int(e.code());
    } catch (const ExpressionError& e) {
        std::fprintf(stderr, "%s: error: expression: %s\n", program.c_str(), e.what());
        return int(ExitCode::EXPRESSION);
    } catch (const sph::SettingsError& e) {
        std::fprintf(stderr, "%s: error: scene setting: %s\n", program.c_str(), e.what());
        return int(ExitCode::SCENE);
    } catch (const sph::ThreadStartError& e) {
        return alone(std::string("error: ") + e.what() +
                         ": run with fewer --threads, or raise the limit on processes or memory "
                         "(ulimit -u, ulimit -v, the batch system's request)",
                     ExitCode::RESOURCES);
    } catch (const std::bad_alloc&) {
        return alone(
            "error: out of memory (try a larger particles.spacing, fewer --threads, or "
            "raise the memory limit: ulimit -v, the batch system's request)",
            ExitCode::RESOURCES);
    } catch (const std::exception& e) {
        return alone(std::string("internal error: ") + e.what() + " (please report it)",
                     ExitCode::INTERNAL);
    }
}

/// Parses the command line; an exit code where it asked for --help or is bad.
std::optional<int> parseCommandLine(CLI::App& app, int argc, char** argv, const std::string& name) {
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::fprintf(stderr, "%s: error: %s (run '%s --help' for the options and examples)\n",
                     name.c_str(), e.what(), name.c_str());
        return int(ExitCode::USAGE);
    }
    return std::nullopt;
}

/// --version and --list-scenes, answered without a scene: their exit code, where one was given.
std::optional<int> answerVersionOrList(const CommandLine& c, int argc, const AppInfo& info) {
    if (c.version) {
        if (argc > 2) {
            std::fprintf(stderr, "%s: error: --version takes no other option or argument\n",
                         info.name.c_str());
            return int(ExitCode::USAGE);
        }
        std::printf("%s (numerics) 0.1.0\nCUDA back end (--backend cuda): %s\n", info.name.c_str(),
                    device::cudaBuilt() ? "built" : "not built (no CUDA compiler at build time)");
        return 0;
    }
    if (c.list) {
        std::error_code ec;
        return listScenes(std::filesystem::is_directory("scenes", ec) ? "scenes" : info.scenesDir,
                          info);
    }
    return std::nullopt;
}

}  // namespace

template <int Dim>
int runApp(int argc, char** argv, const AppInfo& info) {
    // A closed stdout (`fluid_sim | head -1`) must not end the run before its outputs: writes to
    // it fail quietly instead.
    std::signal(SIGPIPE, SIG_IGN);
    std::unique_ptr<parallel::Communicator> comm;
    try {
        comm = std::make_unique<parallel::Communicator>(argc, argv);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s: error: %s\n", info.name.c_str(), e.what());
        return int(ExitCode::USAGE);
    }
    const int ownError = quietUnlessRoot(*comm);
    // An error met by this process alone: reported here, and every process ends at once.
    auto alone = [&](const std::string& text, ExitCode code) {
        if (comm->size() == 1) {
            std::fprintf(stderr, "%s: %s\n", info.name.c_str(), text.c_str());
            return int(code);
        }
        const std::string line = info.name + " (process " + std::to_string(comm->rank()) + " of " +
                                 std::to_string(comm->size()) + "): " + text + "\n";
        if (::write(ownError, line.data(), line.size()) < 0) std::perror(info.name.c_str());
        comm->abort(int(code));
    };
    CLI::App app{"Smoothed Particle Hydrodynamics of water with heat transfer in " +
                     std::to_string(Dim) + "D (numerics 0.1.0).",
                 info.name};
    CommandLine c;
    addOptions(app, c, info);
    app.footer(examples(info.name, Dim));
    if (const auto code = parseCommandLine(app, argc, argv, info.name)) return *code;
    if (const auto code = answerVersionOrList(c, argc, info)) return *code;
    RunOptions& opt = c.options;
    opt.program = info.name, opt.communicator = comm.get(), opt.fieldNames = info.fieldNames;
    opt.backendGiven = app.count("--backend") > 0;
    if (!c.out.empty()) opt.outDir = c.out;
    if (c.endTime > 0) opt.endTime = c.endTime;
    if (!c.restart.empty()) opt.restart = c.restart;
    return reportingErrors(
        info.name,
        [&] {
            const SceneDocument doc = sceneToRun<Dim>(c, info);
            if (!c.printScene) return runSimulation<Dim>(doc, opt);
            std::cout << doc.dump() << "\n";
            return 0;
        },
        alone);
}

template int runApp<2>(int, char**, const AppInfo&);
template int runApp<3>(int, char**, const AppInfo&);

}  // namespace num::app
