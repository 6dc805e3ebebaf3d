// libFuzzer harness of the scene reader: any bytes as a scene file, read as the apps read one
// (JSON, the dimension, every key of a 2D or 3D scene, the geometry). Every outcome must be a
// scene or an error a user can act on (AppError, ExpressionError, SettingsError); anything else
// escaping, a crash or a sanitizer report is a bug.
#include <cstddef>
#include <cstdint>
#include <string>

#include "app/errors.hpp"
#include "app/expression.hpp"
#include "app/scene_loader.hpp"
#include "sph/settings.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace num::app;
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        const SceneDocument doc = SceneDocument::fromText(text, "fuzz.json");
        if (doc.dimension() == 2)
            (void)readScene<2>(doc);
        else
            (void)readScene<3>(doc);
    } catch (const AppError&) {
    } catch (const ExpressionError&) {
    } catch (const num::sph::SettingsError&) {
    }
    return 0;
}
