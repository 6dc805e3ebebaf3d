// Readable names of C++ types for messages ("examples::HeatDiffusion<2>").
#pragma once

#include <cstdlib>
#include <string>
#include <typeinfo>

#if __has_include(<cxxabi.h>)
#include <cxxabi.h>
#endif

namespace num::sph {

inline std::string typeName(const std::type_info& type) {
#if __has_include(<cxxabi.h>)
    int status = 0;
    char* name = abi::__cxa_demangle(type.name(), nullptr, nullptr, &status);
    if (status == 0 && name) {
        std::string text(name);
        std::free(name);
        return text;
    }
#endif
    return type.name();
}

/// The dynamic type of an object (the user's class behind an interface).
template <class T>
std::string typeName(const T& object) {
    return typeName(typeid(object));
}

}  // namespace num::sph
