// A shape that cannot be used as given (a polygon that crosses itself, a mesh with holes): the
// message is one line saying what is wrong and what to do.
#pragma once

#include <stdexcept>

namespace num::geometry {

class GeometryError : public std::invalid_argument {
  public:
    using std::invalid_argument::invalid_argument;
};

}  // namespace num::geometry
