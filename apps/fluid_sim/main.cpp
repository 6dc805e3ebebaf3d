// fluid_sim: 2D water with heat transfer. Without a scene file it runs its built-in scene, hot
// water collapsing onto cold water past a hot and a cold body (scenes/dam_break_hot_cold_2d.json).
// Everything else is shared with fluid_sim_3d: num::app::runApp (include/app/app.hpp).
#include "app/app.hpp"
#include "default_scene.hpp"

int main(int argc, char** argv) {
    return num::app::runApp<2>(
        argc, argv, {"fluid_sim", kDefaultScene, kDefaultSceneName, {}, NUMERICS_SCENES_DIR});
}
