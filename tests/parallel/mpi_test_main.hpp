// The main of a GoogleTest program that runs on the processes mpiexec started (one without it):
// it creates the communicator (tests reach it through `world`), lets the processes other than the
// root report failures only, and makes every process exit alike: 1 when a test failed on any.
#pragma once

#include <gtest/gtest.h>

#include "parallel/communicator.hpp"

namespace num::parallel::testing {

inline const Communicator* world = nullptr;

inline int runTests(int argc, char** argv) {
    const Communicator communicator(argc, argv);
    world = &communicator;
    if (!communicator.isRoot()) GTEST_FLAG_SET(brief, true);
    ::testing::InitGoogleTest(&argc, argv);
    const bool failed = RUN_ALL_TESTS() != 0;
    return communicator.any(failed) ? 1 : 0;
}

}  // namespace num::parallel::testing
