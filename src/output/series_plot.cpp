#include "output/series_plot.hpp"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "app/outputs.hpp"

namespace num::app {

namespace {

namespace fs = std::filesystem;

bool isFile(const fs::path& p) {
    std::error_code ec;
    return fs::is_regular_file(p, ec);
}

/// A word for sh -c: quoted, its quotes escaped.
std::string quoted(const std::string& s) {
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

/// The first line of a file, "" when there is none.
std::string firstLine(const std::string& path) {
    std::ifstream in(path);
    std::string line;
    std::getline(in, line);
    return line;
}

}  // namespace

std::string plotScript() {
    if (const char* s = std::getenv("NUMERICS_PLOT_SCRIPT")) return isFile(s) ? s : "";
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        for (const fs::path& p :
             {exe.parent_path() / "plot_series.py",
              exe.parent_path().parent_path() / "share/numerics/plot_series.py"})
            if (isFile(p)) return p.string();
    }
#ifdef NUMERICS_PLOT_SCRIPT_SOURCE
    if (isFile(NUMERICS_PLOT_SCRIPT_SOURCE)) return NUMERICS_PLOT_SCRIPT_SOURCE;
#endif
    return "";
}

std::string plotPython() {
    if (const char* p = std::getenv("NUMERICS_PYTHON")) return ::access(p, X_OK) == 0 ? p : "";
    if (::access("/usr/bin/python3", X_OK) == 0) return "/usr/bin/python3";
    return onPath("python3") ? "python3" : "";
}

std::string plotSeries(const std::string& csv, const std::vector<std::string>& pictures,
                       const std::string& title, const std::string& log) {
    const std::string script = plotScript(), python = plotPython();
    if (script.empty())
        return "plot_series.py was not found (beside the program, or set NUMERICS_PLOT_SCRIPT)";
    if (python.empty())
        return "python3 is not installed (./scripts/setup.sh or apt-get install python3 "
               "python3-matplotlib adds it)";
    std::string cmd = quoted(python) + " " + quoted(script) + " " + quoted(csv);
    for (const std::string& p : pictures) cmd += " -o " + quoted(p);
    cmd += " --title " + quoted(title) + " >" + quoted(log) + " 2>&1";
    const int rc = std::system(cmd.c_str());
    const std::string message = firstLine(log);
    std::remove(log.c_str());
    if (rc == 0) return "";
    return message.empty() ? "plot_series.py failed (exit status " + std::to_string(rc) + ")"
                           : message;
}

}  // namespace num::app
