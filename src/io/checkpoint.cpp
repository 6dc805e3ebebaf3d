#include "io/checkpoint.hpp"

#include <zlib.h>

#include <cerrno>
#include <fstream>
#include <sstream>

#include "io/file.hpp"

namespace num::io {

using sph::QuantityId;

namespace {
constexpr char kMagic[8] = {'N', 'U', 'M', 'S', 'P', 'H', 'C', 'K'};
constexpr std::size_t kHeader = 8 + 4 + 4 + 8 + 4 + 4;

std::uint32_t crc(const std::string& s) {
    uLong c = crc32(0L, Z_NULL, 0);
    std::size_t pos = 0;
    while (pos < s.size()) {  // crc32 takes at most 4 GiB at once
        const uInt n = uInt(std::min<std::size_t>(s.size() - pos, 1u << 30));
        c = crc32(c, reinterpret_cast<const Bytef*>(s.data() + pos), n);
        pos += n;
    }
    return std::uint32_t(c);
}

template <class T>
constexpr std::int32_t typeTag() {
    return std::is_same_v<T, sph::Float> ? 0 : std::is_same_v<T, int> ? 2 : 1;
}
}  // namespace

void writeCheckpointFile(const std::string& path, int dimension, const std::string& payload) {
    ByteWriter h;
    for (char c : kMagic) h.put(c);
    h.put<std::uint32_t>(kCheckpointVersion);
    h.put<std::uint32_t>(std::uint32_t(dimension));
    h.put<std::uint64_t>(payload.size());
    h.put<std::uint32_t>(crc(payload));
    h.put<std::uint32_t>(0);
    writeFileAtomically(path, h.bytes() + payload);
}

std::string readCheckpointFile(const std::string& path, int dimension) {
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw AppError(ExitCode::CHECKPOINT,
                       path + ": cannot read the checkpoint: " + std::strerror(errno));
    std::ostringstream ss;
    ss << in.rdbuf();
    const std::string all = ss.str();
    auto fail = [&](const std::string& why) {
        throw AppError(ExitCode::CHECKPOINT,
                       path + ": " + why + "; it cannot be used for --restart");
    };
    if (all.size() < kHeader || std::memcmp(all.data(), kMagic, 8) != 0)
        fail(all.size() < 8 ? "the file is too short to be a checkpoint (truncated?)"
                            : "not a numerics checkpoint (wrong magic bytes)");
    ByteReader r(all, path);
    for (int k = 0; k < 8; ++k) r.get<char>();
    const auto version = r.get<std::uint32_t>();
    const auto dim = r.get<std::uint32_t>();
    const auto size = r.get<std::uint64_t>();
    const auto sum = r.get<std::uint32_t>();
    if (version != kCheckpointVersion)
        fail("checkpoint format version " + std::to_string(version) +
             ", this program reads version " + std::to_string(kCheckpointVersion));
    if (int(dim) != dimension)
        fail("a " + std::to_string(dim) + "D checkpoint: restart it with " +
             (dim == 2 ? "fluid_sim" : "fluid_sim_3d"));
    if (all.size() - kHeader < size)
        fail("the file is truncated (" + std::to_string(all.size()) + " bytes, expected " +
             std::to_string(kHeader + size) + ")");
    if (all.size() - kHeader > size) fail("the file has trailing bytes (corrupted)");
    std::string payload = all.substr(kHeader);
    if (crc(payload) != sum) fail("the checksum does not match: the file is corrupted");
    return payload;
}

template <int Dim>
void writeStorage(ByteWriter& w, const sph::Storage<Dim>& s) {
    w.put<std::uint64_t>(s.size());
    std::uint64_t count = 0;
    s.forEach([&](QuantityId, const auto&) { ++count; });
    w.put<std::uint64_t>(count);
    s.forEach([&](QuantityId id, const sph::Quantity<Dim>& q) {
        w.put<std::int32_t>(int(id));
        w.put<std::int32_t>(int(q.order()));
        q.visit([&](const auto& b) {
            using T = typename std::decay_t<decltype(b.value)>::value_type;
            w.put<std::int32_t>(typeTag<T>());
            for (int k = 0; k < q.levels(); ++k) w.putVector(b.level(k));
        });
    });
    w.put<std::uint64_t>(s.materials().size());
    for (const auto& m : s.materials()) w.putString(m ? m->name() : "");
}

template <int Dim>
sph::Storage<Dim> readStorage(ByteReader& r, const sph::Storage<Dim>& materials) {
    sph::Storage<Dim> s;
    const auto n = r.get<std::uint64_t>();
    const auto count = r.get<std::uint64_t>();
    auto load = [&](auto tag, QuantityId id, sph::OrderEnum order) {
        using T = decltype(tag);
        auto& q = s.template insert<T>(id, order, r.getVector<T>());
        auto& b = q.template buffers<T>();
        for (int k = 1; k <= int(order); ++k) b.level(k) = r.getVector<T>();
        for (int k = 0; k <= int(order); ++k)
            if (b.level(k).size() != n)
                throw AppError(
                    ExitCode::CHECKPOINT,
                    "checkpoint: quantity " + std::to_string(int(id)) + " has the wrong length");
    };
    for (std::uint64_t k = 0; k < count; ++k) {
        const auto id = QuantityId(r.get<std::int32_t>());
        const auto order = r.get<std::int32_t>();
        const auto tag = r.get<std::int32_t>();
        if (order < 0 || order > 2 || tag < 0 || tag > 2)
            throw AppError(ExitCode::CHECKPOINT, "checkpoint: invalid quantity record");
        const auto o = sph::OrderEnum(order);
        if (tag == 0)
            load(sph::Float{}, id, o);
        else if (tag == 1)
            load(sph::Vector<Dim>{}, id, o);
        else
            load(int{}, id, o);
    }
    const auto names = r.get<std::uint64_t>();
    if (names != materials.materials().size())
        throw AppError(ExitCode::CHECKPOINT, "checkpoint: it was written with " +
                                                 std::to_string(names) +
                                                 " materials, the scene has " +
                                                 std::to_string(materials.materials().size()));
    for (std::uint64_t k = 0; k < names; ++k) {
        const std::string name = r.getString();
        if (name != materials.materials()[k]->name())
            throw AppError(ExitCode::CHECKPOINT, "checkpoint: material " + std::to_string(k) +
                                                     " is '" + name + "', the scene's is '" +
                                                     materials.materials()[k]->name() + "'");
    }
    s.materials() = materials.materials();
    return s;
}

template void writeStorage<2>(ByteWriter&, const sph::Storage<2>&);
template void writeStorage<3>(ByteWriter&, const sph::Storage<3>&);
template sph::Storage<2> readStorage<2>(ByteReader&, const sph::Storage<2>&);
template sph::Storage<3> readStorage<3>(ByteReader&, const sph::Storage<3>&);

}  // namespace num::io
