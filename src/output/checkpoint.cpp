#include "app/checkpoint.hpp"

#include <zlib.h>

#include <cerrno>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "app/file.hpp"
#include "app/formatted.hpp"

namespace num::app {

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

std::string checkpointBytes(int dimension, const std::string& payload) {
    ByteWriter h;
    for (char c : kMagic) h.put(c);
    h.put<std::uint32_t>(kCheckpointVersion);
    h.put<std::uint32_t>(std::uint32_t(dimension));
    h.put<std::uint64_t>(payload.size());
    h.put<std::uint32_t>(crc(payload));
    h.put<std::uint32_t>(0);
    return h.bytes() + payload;
}

void writeCheckpointFile(const std::string& path, int dimension, const std::string& payload) {
    writeFileAtomically(path, checkpointBytes(dimension, payload));
}

namespace {
[[noreturn]] void refuse(const std::string& path, const std::string& why) {
    throw AppError(ExitCode::CHECKPOINT, path + ": " + why + "; it cannot be used for --restart");
}

/// Checks a checkpoint's header against the file's size (`bytes`, or -1 where unknown), before
/// its payload is read: a file that is not a checkpoint, or claims more than it holds, is
/// refused without reading it whole.
std::uint64_t checkHeader(const std::string& header, long double bytes, const std::string& path,
                          int dimension) {
    if (header.size() < kHeader || std::memcmp(header.data(), kMagic, 8) != 0)
        refuse(path, header.size() < 8 ||
                             (header.size() < kHeader && std::memcmp(header.data(), kMagic, 8) == 0)
                         ? "the file is too short to be a checkpoint (truncated?)"
                         : "not a numerics checkpoint (wrong magic bytes)");
    ByteReader r(header, path);
    for (int k = 0; k < 8; ++k) r.get<char>();
    const auto version = r.get<std::uint32_t>();
    const auto dim = r.get<std::uint32_t>();
    const auto size = r.get<std::uint64_t>();
    if (version != kCheckpointVersion)
        refuse(path, "checkpoint format version " + std::to_string(version) +
                         ", this program reads version " + std::to_string(kCheckpointVersion));
    if (dim != 2 && dim != 3)
        refuse(path, "the header names dimension " + std::to_string(dim) +
                         " (2 or 3 expected): the file is corrupted");
    if (int(dim) != dimension)
        refuse(path, "a " + std::to_string(dim) + "D checkpoint: restart it with " +
                         (dim == 2 ? "fluid_sim" : "fluid_sim_3d"));
    if (bytes >= 0 && bytes - kHeader < (long double)size)
        refuse(path, "the file is truncated (" + formatted("%.0Lf", bytes) + " bytes, expected " +
                         formatted("%.0Lf", (long double)kHeader + size) + ")");
    if (bytes >= 0 && bytes - kHeader > (long double)size)
        refuse(path, "the file has trailing bytes (corrupted)");
    return size;
}
}  // namespace

std::string checkpointPayload(const std::string& all, const std::string& path, int dimension) {
    checkHeader(all.substr(0, kHeader), (long double)all.size(), path, dimension);
    ByteReader r(all, path);
    for (std::size_t k = 0; k < kHeader - 8; ++k) r.get<char>();
    const auto sum = r.get<std::uint32_t>();
    std::string payload = all.substr(kHeader);
    if (crc(payload) != sum) refuse(path, "the checksum does not match: the file is corrupted");
    return payload;
}

std::string readCheckpointFile(const std::string& path, int dimension) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec))
        refuse(path, "it is a directory, not a checkpoint file");
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw AppError(ExitCode::CHECKPOINT,
                       path + ": cannot read the checkpoint: " + std::strerror(errno));
    // The header first: its size is checked against the file's before the payload is read.
    std::string header(kHeader, '\0');
    in.read(header.data(), std::streamsize(kHeader));
    header.resize(std::size_t(in.gcount()));
    const auto fileSize = std::filesystem::is_regular_file(path, ec)
                              ? (long double)std::filesystem::file_size(path, ec)
                              : -1.0L;
    const std::uint64_t size = checkHeader(header, ec ? -1.0L : fileSize, path, dimension);
    // A file that is not a regular one (a pipe) is read up to the size its header names.
    std::string all = header;
    try {
        all.resize(kHeader + std::size_t(size));
    } catch (const std::exception&) {
        refuse(path, "the header names a payload of " + std::to_string(size) +
                         " bytes, more than this machine can hold");
    }
    in.read(all.data() + kHeader, std::streamsize(size));
    if (std::uint64_t(in.gcount()) != size)
        refuse(path, "the file is truncated (" + std::to_string(kHeader + in.gcount()) +
                         " bytes, expected " + std::to_string(kHeader + size) + ")");
    if (in.peek() != std::char_traits<char>::eof())
        refuse(path, "the file has trailing bytes (corrupted)");
    return checkpointPayload(all, path, dimension);
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

namespace {

[[noreturn]] void refuseInconsistent(const std::string& file, const std::string& why) {
    throw AppError(ExitCode::CHECKPOINT,
                   file + ": the checkpoint's particles are inconsistent: " + why +
                       "; it cannot be used for --restart (was it edited?)");
}

/// Every quantity the scene's particles have, with their value type; positions, materials and
/// kinds present.
template <int Dim>
void checkQuantities(const sph::Storage<Dim>& s, const sph::Storage<Dim>& initial,
                     const std::string& file) {
    initial.forEach([&](QuantityId id, const sph::Quantity<Dim>& q) {
        if (id == QuantityId::OWNER) return;  // assigned again on restart
        if (!s.has(id))
            refuseInconsistent(file, "quantity " + std::to_string(int(id)) + " is missing");
        q.visit([&](const auto& b) {
            using T = typename std::decay_t<decltype(b.value)>::value_type;
            if (!s.get(id).template holds<T>())
                refuseInconsistent(
                    file, "quantity " + std::to_string(int(id)) + " has another value type");
        });
    });
    if (!s.has(QuantityId::POSITION) || !s.has(QuantityId::MATERIAL) || !s.has(QuantityId::KIND) ||
        !s.get(QuantityId::POSITION).template holds<sph::Vector<Dim>>() ||
        !s.get(QuantityId::MATERIAL).template holds<int>() ||
        !s.get(QuantityId::KIND).template holds<int>())
        refuseInconsistent(file, "positions, materials or kinds are missing or of another type");
}

/// Material indices within the material table, kinds known.
template <int Dim>
void checkIndices(const sph::Storage<Dim>& s, const sph::Storage<Dim>& initial,
                  const std::string& file) {
    const auto material = s.template getValue<int>(QuantityId::MATERIAL);
    const auto kind = s.template getValue<int>(QuantityId::KIND);
    const int materials = int(initial.materials().size());
    for (sph::Size i = 0; i < s.size(); ++i) {
        if (material[i] < 0 || material[i] >= materials)
            refuseInconsistent(file, "particle " + std::to_string(i) + " has material " +
                                         std::to_string(material[i]) + " of " +
                                         std::to_string(materials));
        if (kind[i] < 0 || kind[i] >= sph::kParticleKinds)
            refuseInconsistent(
                file, "particle " + std::to_string(i) + " has kind " + std::to_string(kind[i]));
    }
}

/// Every value finite, at every derivative level.
template <int Dim>
void checkFinite(const sph::Storage<Dim>& s, const std::string& file) {
    s.forEach([&](QuantityId id, const sph::Quantity<Dim>& q) {
        q.visit([&](const auto& b) {
            using T = typename std::decay_t<decltype(b.value)>::value_type;
            if constexpr (!std::is_same_v<T, int>)
                for (int level = 0; level < q.levels(); ++level)
                    for (const T& value : b.level(level)) {
                        bool finite = true;
                        if constexpr (std::is_same_v<T, sph::Float>)
                            finite = std::isfinite(value);
                        else
                            for (int k = 0; k < Dim; ++k) finite &= std::isfinite(value[k]);
                        if (!finite)
                            refuseInconsistent(file, "quantity " + std::to_string(int(id)) +
                                                         " holds a value that is not finite");
                    }
        });
    });
}

/// A state the run would stop at on its first step (physical_check.hpp): a fluid particle at or
/// above its material's sound speed, or at a density beyond half or twice its rest.
template <int Dim>
void checkPhysicalState(const sph::Storage<Dim>& s, const sph::Storage<Dim>& initial,
                        const std::string& file) {
    if (!s.has(QuantityId::DENSITY) || !s.get(QuantityId::DENSITY).template holds<sph::Float>() ||
        s.order(QuantityId::POSITION) != sph::OrderEnum::SECOND)
        return;
    const auto material = s.template getValue<int>(QuantityId::MATERIAL);
    const auto kind = s.template getValue<int>(QuantityId::KIND);
    const auto v = s.template getDt<sph::Vector<Dim>>(QuantityId::POSITION);
    const auto rho = s.template getValue<sph::Float>(QuantityId::DENSITY);
    for (sph::Size i = 0; i < s.size(); ++i) {
        if (kind[i] != int(sph::ParticleKind::FLUID)) continue;
        const auto& params = initial.materials()[material[i]]->params();
        const double rho0 = params.template get<double>("density");
        const double c0 = params.template get<double>("sound_speed");
        if (!(norm(v[i]) < c0))
            refuseInconsistent(file, "fluid particle " + std::to_string(i) + " moves at " +
                                         formatted("%.3g", norm(v[i])) +
                                         " m/s, at or above the sound speed " +
                                         formatted("%.3g", c0) + " m/s");
        if (!(rho[i] >= 0.5 * rho0 && rho[i] <= 2 * rho0))
            refuseInconsistent(file, "fluid particle " + std::to_string(i) + " has the density " +
                                         formatted("%.3g", rho[i]) + " kg/m^3, its rest density " +
                                         formatted("%.3g", rho0));
    }
}

/// The checks of a checkpoint's particles against the scene's (`initial`). A checkpoint edited by
/// hand (its checksum rewritten) is refused here rather than crash the run.
template <int Dim>
void checkStorage(const sph::Storage<Dim>& s, const sph::Storage<Dim>& initial,
                  const std::string& file) {
    checkQuantities(s, initial, file);
    checkIndices(s, initial, file);
    checkFinite(s, file);
    checkPhysicalState(s, initial, file);
}

}  // namespace

template <int Dim>
sph::Storage<Dim> readStorage(ByteReader& r, const sph::Storage<Dim>& materials) {
    sph::Storage<Dim> s;
    auto refuse = [&](const std::string& why) {
        throw AppError(ExitCode::CHECKPOINT, r.file() + ": the checkpoint's particles are " + why +
                                                 "; it cannot be used for --restart");
    };
    const auto n = r.get<std::uint64_t>();
    const auto count = r.get<std::uint64_t>();
    auto load = [&](auto tag, QuantityId id, sph::OrderEnum order) {
        using T = decltype(tag);
        if (s.has(id)) refuse("inconsistent: quantity " + std::to_string(int(id)) + " twice");
        std::vector<T> value = r.getVector<T>();
        if (value.size() != n)
            refuse("inconsistent: quantity " + std::to_string(int(id)) + " has the wrong length");
        auto& q = s.template insert<T>(id, order, std::move(value));
        auto& b = q.template buffers<T>();
        for (int k = 1; k <= int(order); ++k) b.level(k) = r.getVector<T>();
        for (int k = 0; k <= int(order); ++k)
            if (b.level(k).size() != n)
                refuse("inconsistent: quantity " + std::to_string(int(id)) +
                       " has the wrong length");
    };
    for (std::uint64_t k = 0; k < count; ++k) {
        const auto id = QuantityId(r.get<std::int32_t>());
        const auto order = r.get<std::int32_t>();
        const auto tag = r.get<std::int32_t>();
        if (order < 0 || order > 2 || tag < 0 || tag > 2)
            refuse("inconsistent: an invalid quantity record");
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
        refuse("of another scene: it was written with " + std::to_string(names) +
               " materials, the scene has " + std::to_string(materials.materials().size()));
    for (std::uint64_t k = 0; k < names; ++k) {
        const std::string name = r.getString();
        if (name != materials.materials()[k]->name())
            refuse("of another scene: material " + std::to_string(k) + " is '" + name +
                   "', the scene's is '" + materials.materials()[k]->name() + "'");
    }
    if (!r.atEnd()) refuse("inconsistent: bytes follow the last quantity");
    if (count == 0) s.resize(sph::Size(n));
    s.materials() = materials.materials();
    checkStorage(s, materials, r.file());
    return s;
}

template void writeStorage<2>(ByteWriter&, const sph::Storage<2>&);
template void writeStorage<3>(ByteWriter&, const sph::Storage<3>&);
template sph::Storage<2> readStorage<2>(ByteReader&, const sph::Storage<2>&);
template sph::Storage<3> readStorage<3>(ByteReader&, const sph::Storage<3>&);

}  // namespace num::app
