// numerics: the whole public API of the SPH library.
#pragma once

#include "spatial/cell_grid.hpp"
#include "spatial/kernels.hpp"
#include "spatial/sph_kernel.hpp"
#include "spatial/vec.hpp"
#include "sph/derivative.hpp"
#include "sph/equation_term.hpp"
#include "sph/kernel_choice.hpp"
#include "sph/scheduler.hpp"
#include "sph/settings.hpp"
#include "sph/solver.hpp"
#include "sph/storage.hpp"
#include "sph/timestepping.hpp"
#include "sph/types.hpp"
