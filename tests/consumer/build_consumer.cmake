# Builds and runs the consumer project of tests/consumer/project both ways a user can take
# numerics: (a) add_subdirectory of the source tree, (b) cmake --install into a prefix, then
# find_package(numerics). Run with
#   cmake -DNUMERICS_SOURCE_DIR=<src> -DWORK_DIR=<scratch> [-DGENERATOR=<gen>]
#         [-DCXX_COMPILER=<c++>] -P build_consumer.cmake
# Everything comes from the local machine; nothing is downloaded.
cmake_minimum_required(VERSION 3.25)

foreach(var NUMERICS_SOURCE_DIR WORK_DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "build_consumer.cmake: -D${var}=... is required")
  endif()
endforeach()

set(project_dir ${CMAKE_CURRENT_LIST_DIR}/project)
set(common_args -DCMAKE_BUILD_TYPE=Release)
if(GENERATOR)
  list(APPEND common_args -G ${GENERATOR})
endif()
if(CXX_COMPILER)
  list(APPEND common_args -DCMAKE_CXX_COMPILER=${CXX_COMPILER})
endif()

# Runs a command, stops with its output if it fails.
function(run_step what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "consumer: ${what} failed (${rc}):\n${out}")
  endif()
  message(STATUS "consumer: ${what}: ok")
  set(step_output "${out}" PARENT_SCOPE)
endfunction()

function(build_and_run_consumer mode build_dir)
  run_step("configure consumer (${mode})" ${CMAKE_COMMAND} -S ${project_dir} -B ${build_dir}
           ${common_args} -DNUMERICS_CONSUMER_MODE=${mode} ${ARGN})
  run_step("build consumer (${mode})" ${CMAKE_COMMAND} --build ${build_dir} -j 2)
  run_step("run consumer (${mode})" ${build_dir}/app)
  message(STATUS "${step_output}")
endfunction()

file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})

# (a) the numerics source tree as a sub-project.
build_and_run_consumer(subdirectory ${WORK_DIR}/subdirectory
                       -DNUMERICS_SOURCE_DIR=${NUMERICS_SOURCE_DIR})

# (b) installed numerics found with find_package.
set(prefix ${WORK_DIR}/prefix)
run_step("configure numerics for install" ${CMAKE_COMMAND} -S ${NUMERICS_SOURCE_DIR}
         -B ${WORK_DIR}/numerics-build ${common_args} -DCMAKE_INSTALL_PREFIX=${prefix}
         -DNUMERICS_BUILD_APPS=OFF -DNUMERICS_BUILD_TESTS=OFF -DNUMERICS_BUILD_BENCH=OFF
         -DNUMERICS_BUILD_EXAMPLES=OFF -DNUMERICS_BUILD_APP=OFF)
run_step("build numerics" ${CMAKE_COMMAND} --build ${WORK_DIR}/numerics-build -j 2)
run_step("install numerics" ${CMAKE_COMMAND} --install ${WORK_DIR}/numerics-build)
build_and_run_consumer(package ${WORK_DIR}/package -DCMAKE_PREFIX_PATH=${prefix})

file(REMOVE_RECURSE ${WORK_DIR})
