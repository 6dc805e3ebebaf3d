// fluid_sim_3d: 3D water with heat transfer. Without a scene file it runs its built-in scene, hot
// (70 C) and cold (10 C) water changing places in a tank past a hot and a cold block
// (scenes/hot_cold_exchange_3d.json). Everything else is shared with fluid_sim: num::app::runApp
// (include/app/app.hpp).
#include "app/app.hpp"
#include "default_scene.hpp"

int main(int argc, char** argv) {
    return num::app::runApp<3>(
        argc, argv, {"fluid_sim_3d", kDefaultScene, kDefaultSceneName, {}, NUMERICS_SCENES_DIR});
}
