// libFuzzer harness of the checkpoint reader: the first byte chooses how the rest is read, as a
// whole file (header and payload; the checksum then rejects most edits) or as a payload given a
// valid header and checksum (what an edit with a rewritten checksum looks like), and as a 2D or
// 3D checkpoint. The payload is read as a restart reads it: the stored scene, the fingerprint (as
// text: comparing it needs the run's set-up), the run state and every quantity. Every outcome must
// be an AppError (CHECKPOINT, or a scene error of the stored scene); anything else escaping, a
// crash or a sanitizer report is a bug.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

#include "app/checkpoint.hpp"
#include "app/errors.hpp"
#include "app/expression.hpp"
#include "app/scene_loader.hpp"
#include "run/checkpoint_state.hpp"
#include "sph/settings.hpp"

namespace {

using namespace num;

template <int Dim>
void readCheckpoint(const std::string& bytes) {
    const std::string path = "fuzz.chk";
    const std::string payload = app::checkpointPayload(bytes, path, Dim);
    app::ByteReader r(payload, path);
    const app::SceneDocument doc = app::SceneDocument::fromText(r.getString(), path + " (scene)");
    (void)doc.dimension();
    (void)r.getString();  // the fingerprint: text compared line by line (fingerprint.hpp)
    app::RunState<Dim> state;
    state.read(r);
    // The material table a restart of the stored scene has: its materials in name order.
    sph::Storage<Dim> materials;
    const auto& table = doc.json().contains("materials") ? doc.json()["materials"] : nullptr;
    if (table.is_object())
        for (const auto& [name, value] : table.items())
            materials.materials().push_back(std::make_shared<sph::Material>(name));
    const sph::Storage<Dim> s = app::readStorage<Dim>(r, materials);
    (void)s.size();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return 0;
    const int mode = data[0];
    const int dim = mode & 2 ? 3 : 2;
    std::string bytes(reinterpret_cast<const char*>(data) + 1, size - 1);
    if (mode & 1) bytes = app::checkpointBytes(dim, bytes);
    try {
        if (dim == 2)
            readCheckpoint<2>(bytes);
        else
            readCheckpoint<3>(bytes);
    } catch (const app::AppError&) {
    } catch (const app::ExpressionError&) {
    } catch (const sph::SettingsError&) {
    }
    return 0;
}
