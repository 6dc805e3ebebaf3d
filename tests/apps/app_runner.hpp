// Running the apps from tests: a command line in, exit code and output (stdout + stderr) out;
// fresh work directories; small file helpers.
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace apptest {

struct Result {
    int code = -1;
    std::string output;
};

/// Runs `program args` with the shell in `dir`, capturing stdout and stderr.
inline Result run(const std::string& program, const std::string& args, const std::string& dir) {
    const std::string cmd = "cd '" + dir + "' && '" + program + "' " + args + " 2>&1";
    Result r;
    std::FILE* p = popen(cmd.c_str(), "r");
    if (!p) return r;
    char buf[4096];
    std::size_t n;
    while ((n = std::fread(buf, 1, sizeof buf, p)) > 0) r.output.append(buf, n);
    const int status = pclose(p);
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

/// An empty directory for one test.
inline std::string freshDir(const std::string& name) {
    const std::string dir = std::string(APP_TEST_WORK) + "/" + name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

inline std::string scene(const std::string& name) {
    return std::string(APP_TEST_SCENES) + "/" + name;
}

inline std::string readFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

inline void writeFile(const std::string& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

inline bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

/// A refusal: exit code `code` and one line of output that names every part.
inline void expectOneLine(const Result& r, int code, std::initializer_list<const char*> parts) {
    EXPECT_EQ(r.code, code) << r.output;
    for (const char* p : parts)
        EXPECT_TRUE(contains(r.output, p)) << "missing '" << p << "' in:\n" << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
}

/// A CSV file with a header line (particles_*.csv, probes.csv): column name -> values.
using Table = std::map<std::string, std::vector<double>>;

inline Table readCsv(const std::string& path) {
    std::ifstream in(path);
    std::string line;
    Table table;
    std::vector<std::string> names;
    if (std::getline(in, line)) {
        std::stringstream s(line);
        for (std::string n; std::getline(s, n, ',');) names.push_back(n);
    }
    while (std::getline(in, line)) {
        std::stringstream s(line);
        std::string cell;
        for (std::size_t k = 0; k < names.size() && std::getline(s, cell, ','); ++k)
            table[names[k]].push_back(std::stod(cell));
    }
    return table;
}

}  // namespace apptest
