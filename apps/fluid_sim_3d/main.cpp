// fluid_sim_3d: 3D water with heat transfer. Without a scene file it runs its built-in scene, a
// cold (5 C) and a hot (80 C) hose pouring into a closed box (scenes/hoses_3d.json). Everything
// else is shared with fluid_sim: num::io::runApp (include/io/app.hpp).
#include "default_scene.hpp"
#include "io/app.hpp"

int main(int argc, char** argv) {
    return num::io::runApp<3>(
        argc, argv, {"fluid_sim_3d", kDefaultScene, kDefaultSceneName, {}, NUMERICS_SCENES_DIR});
}
