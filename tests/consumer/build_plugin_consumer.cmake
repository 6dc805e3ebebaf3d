# The plugin walkthrough of docs/extending.md as a user follows it, from a clean install
# prefix: numerics (library, numerics::app, headers, CMake package) is installed into an empty
# prefix; the walkthrough's damping.cpp, CMakeLists.txt and damped.json, taken from the document,
# are built with numerics_add_plugin against that prefix alone and run with the built fluid_sim.
# Run with
#   cmake -DNUMERICS_SOURCE_DIR=<src> -DBUILD_DIR=<built numerics tree> -DWORK_DIR=<scratch>
#         -DFLUID_SIM=<fluid_sim> [-DGENERATOR=<gen>] [-DCXX_COMPILER=<c++>]
#         -P build_plugin_consumer.cmake
# Everything comes from the local machine; nothing is downloaded.
cmake_minimum_required(VERSION 3.25)

foreach(var NUMERICS_SOURCE_DIR BUILD_DIR WORK_DIR FLUID_SIM)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "build_plugin_consumer.cmake: -D${var}=... is required")
  endif()
endforeach()

# Debug: the plugin builds unoptimised; the walkthrough's scene is small, and the plugin's speed
# is not what this test checks.
set(common_args -DCMAKE_BUILD_TYPE=Debug)
if(GENERATOR)
  list(APPEND common_args -G ${GENERATOR})
endif()
if(CXX_COMPILER)
  list(APPEND common_args -DCMAKE_CXX_COMPILER=${CXX_COMPILER})
endif()

function(run_step what)
  cmake_parse_arguments(S "" "WORKING_DIRECTORY" "" ${ARGN})
  if(NOT S_WORKING_DIRECTORY)
    set(S_WORKING_DIRECTORY ${WORK_DIR})
  endif()
  execute_process(COMMAND ${S_UNPARSED_ARGUMENTS} WORKING_DIRECTORY ${S_WORKING_DIRECTORY}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "plugin consumer: ${what} failed (${rc}):\n${out}")
  endif()
  message(STATUS "plugin consumer: ${what}: ok")
  set(step_output "${out}" PARENT_SCOPE)
endfunction()

file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})

# 1. Install the built numerics (libraries, headers, CMake package) into an empty prefix, as
#    `cmake --install` does after a user's build.
set(prefix ${WORK_DIR}/prefix)
run_step("install numerics" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})

# 2. The walkthrough's files, from docs/extending.md.
run_step("extract the walkthrough" /usr/bin/python3
         ${NUMERICS_SOURCE_DIR}/tests/docs/extract_blocks.py
         ${NUMERICS_SOURCE_DIR}/docs/extending.md ${WORK_DIR}/doc)
set(project ${WORK_DIR}/doc/plugin)

# 3. Build the plugin as the walkthrough says: against the prefix only.
run_step("configure the plugin" ${CMAKE_COMMAND} -S ${project} -B ${project}/build
         ${common_args} -DCMAKE_PREFIX_PATH=${prefix})
run_step("build the plugin" ${CMAKE_COMMAND} --build ${project}/build)
if(NOT EXISTS ${project}/build/libdamping.so)
  message(FATAL_ERROR "plugin consumer: numerics_add_plugin made no build/libdamping.so")
endif()

# 4. Run the walkthrough's scene with the built fluid_sim.
run_step("run fluid_sim damped.json" ${FLUID_SIM} damped.json --out out -q --threads 1
         WORKING_DIRECTORY ${project})

# 5. The field is written, and the drag did what it says: a uniform flow in a periodic box
#    (no walls: the fluid's pair forces cancel in the mean) slows as v0 exp(-gamma t). The
#    leapfrog evaluates this velocity-dependent force with the velocity of the half step before,
#    an error of about gamma dt per unit gamma t: with dt ~ 1.4 ms (Courant) and gamma t = 0.2,
#    below 1e-3 of v0, the tolerance (measured 2e-4; a gamma off by 1 % is off by 1.6e-3).
file(GLOB outputs ${project}/out/particles_*.csv)
list(SORT outputs)
list(GET outputs -1 last)
run_step("check the damping" /usr/bin/python3 -c "
import csv, json, math, sys
scene = json.load(open('${project}/damped.json'))
rows = list(csv.DictReader(open('${last}')))
term = scene['plugins'][0]['terms'][0]
v0, t = scene['fluids'][0]['velocity'][0], scene['time']['end']
expected = v0 * math.exp(-term['gamma'] * t)
vx = sum(float(r['vx']) for r in rows) / len(rows)
power = sum(float(r['damping_power']) for r in rows)
print('mean vx', vx, 'expected', expected, 'damping_power', power)
sys.exit(0 if abs(vx - expected) < 1e-3 * v0 and power > 0 else 1)
")
message(STATUS "${step_output}")
file(REMOVE_RECURSE ${WORK_DIR})
