// Checks of a mesh file before a reader trusts it (mesh_file_check.hpp).
#include "geometry/mesh_file_check.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "geometry/geometry_error.hpp"

namespace num::geometry {

namespace {

const char* const kGive = ": give an STL, OBJ or PLY file of triangles";

[[noreturn]] void refuse(const std::string& path, const std::string& why) {
    throw GeometryError(path + ": not a readable mesh (" + why + ")" + kGive);
}

/// A count read from a file as it would be written: 255, 2.5, -1, nan.
std::string countText(double n) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", n);
    return text;
}

/// Bytes of a PLY scalar type, 0 for an unknown name.
int plyTypeSize(const std::string& t) {
    if (t == "char" || t == "uchar" || t == "int8" || t == "uint8") return 1;
    if (t == "short" || t == "ushort" || t == "int16" || t == "uint16") return 2;
    if (t == "int" || t == "uint" || t == "int32" || t == "uint32" || t == "float" ||
        t == "float32")
        return 4;
    if (t == "double" || t == "float64") return 8;
    return 0;
}

struct PlyProperty {
    std::string name;
    int size = 0;       ///< of the value, or of each list item
    int countSize = 0;  ///< > 0: a list, with a count of this many bytes
    bool isFloat = false, countSigned = false, itemSigned = false;
};

struct PlyElement {
    std::string name;
    std::uint64_t count = 0;
    std::vector<PlyProperty> properties;
};

/// A value of the file as text: an index as an integer, any other number too (1e+49, nan), where
/// a cast to an integer would be undefined.
std::string number(double v) {
    char s[32];
    std::snprintf(s, sizeof s, "%.15g", v);
    return s;
}

bool isSignedType(const std::string& t) {
    return t == "char" || t == "int8" || t == "short" || t == "int16" || t == "int" ||
           t == "int32" || t == "float" || t == "float32" || t == "double" || t == "float64";
}

bool isFloatType(const std::string& t) {
    return t == "float" || t == "float32" || t == "double" || t == "float64";
}

/// Reads the bytes of a binary PLY body one value at a time, refusing a body cut short.
class BinaryBody {
  public:
    BinaryBody(std::ifstream& in, bool bigEndian, const std::string& path)
        : in_(in), big_(bigEndian), path_(path) {}
    /// A value of `size` bytes as an integer (signed or not) or, for floats, as a double.
    double value(int size, bool isSigned, bool isFloat) {
        unsigned char b[8];
        if (size < 1 || size > 8) refuse(path_, "a binary PLY value of more than 8 bytes");
        if (!in_.read(reinterpret_cast<char*>(b), size))
            refuse(path_, "the binary PLY body ends before the elements its header announces");
        if (big_) std::reverse(b, b + size);
        if (isFloat) {
            if (size == 4) {
                float f;
                std::memcpy(&f, b, 4);
                return f;
            }
            double d;
            std::memcpy(&d, b, 8);
            return d;
        }
        std::uint64_t u = 0;
        for (int k = size - 1; k >= 0; --k) u = (u << 8) | b[k];
        if (isSigned && size < 8 && (u >> (8 * size - 1)) != 0)
            return double(u) - std::ldexp(1.0, 8 * size);
        return double(u);
    }

  private:
    std::ifstream& in_;
    bool big_;
    const std::string& path_;
};

/// Reads the tokens of an ASCII PLY body, refusing a body cut short or a token not a number.
class AsciiBody {
  public:
    AsciiBody(std::ifstream& in, const std::string& path) : in_(in), path_(path) {}
    double value() {
        std::string t;
        if (!(in_ >> t))
            refuse(path_, "the ASCII PLY body ends before the elements its header announces");
        char* end = nullptr;
        const double v = std::strtod(t.c_str(), &end);
        if (t.empty() || *end != '\0')  // appended: g++ 12 warns wrongly on "'" + string there
            refuse(path_,
                   std::string("'").append(t, 0, 40).append("' in the PLY body is not a number"));
        return v;
    }

  private:
    std::ifstream& in_;
    const std::string& path_;
};

/// Reads one value of a PLY body, binary or ASCII as its format says.
class PlyBody {
  public:
    PlyBody(std::ifstream& in, const std::string& format, const std::string& path)
        : binary_(format != "ascii"),
          bin_(in, format == "binary_big_endian", path),
          text_(in, path) {}
    bool binary() const { return binary_; }
    /// A plain property's value, or one item of a list.
    double item(const PlyProperty& p) {
        return binary_ ? bin_.value(p.size, p.itemSigned, p.isFloat) : text_.value();
    }
    /// The length of a list.
    double count(const PlyProperty& p) {
        return binary_ ? bin_.value(p.countSize, p.countSigned, false) : text_.value();
    }

  private:
    bool binary_;
    BinaryBody bin_;
    AsciiBody text_;
};

/// The offset just past the "end_header" line, which must start a line within the header's bytes.
std::size_t plyHeaderEnd(const std::string& header, const std::string& path) {
    for (std::size_t at = 0; (at = header.find("end_header", at)) != std::string::npos; ++at) {
        const bool lineStart = at > 0 && header[at - 1] == '\n';
        const std::size_t after = at + 10;
        if (lineStart && after < header.size() && (header[after] == '\n' || header[after] == '\r'))
            return header.find('\n', after) + 1;
    }
    refuse(path, "a PLY header without an end_header line in its first " +
                     std::to_string(kMaxPlyHeader) + " bytes");
}

/// An "element NAME COUNT" line's element, its count a whole number within kMaxMeshElements.
PlyElement readPlyElement(std::istringstream& words, const std::string& path) {
    PlyElement e;
    std::string count;
    words >> e.name >> count;
    char* end = nullptr;
    const double n = std::strtod(count.c_str(), &end);
    if (count.empty() || *end != '\0' || !(n >= 0) || n != std::floor(n))
        refuse(path, "PLY element '" + e.name.substr(0, 40) + "' has the count '" +
                         count.substr(0, 40) + "'");
    if (n > double(kMaxMeshElements))
        refuse(path, "the PLY header announces " + count.substr(0, 40) + " " +
                         e.name.substr(0, 40) + " elements, more than " +
                         std::to_string(kMaxMeshElements));
    e.count = std::uint64_t(n);
    return e;
}

/// A "property TYPE NAME" or "property list COUNT_TYPE ITEM_TYPE NAME" line's property.
PlyProperty readPlyProperty(std::istringstream& words, const std::string& path) {
    PlyProperty p;
    std::string type;
    words >> type;
    if (type == "list") {
        std::string countType, itemType;
        words >> countType >> itemType >> p.name;
        p.countSize = plyTypeSize(countType), p.size = plyTypeSize(itemType);
        if (p.countSize == 0 || p.size == 0 || isFloatType(countType))
            refuse(path, "PLY list property '" + p.name.substr(0, 40) + "' of unknown types");
        p.countSigned = isSignedType(countType);
        p.itemSigned = isSignedType(itemType), p.isFloat = isFloatType(itemType);
        return p;
    }
    words >> p.name;
    p.size = plyTypeSize(type);
    if (p.size == 0)
        refuse(path, "PLY property '" + p.name.substr(0, 40) + "' of unknown type '" +
                         type.substr(0, 40) + "'");
    p.itemSigned = isSignedType(type), p.isFloat = isFloatType(type);
    return p;
}

struct PlyHeader {
    std::string format;
    std::vector<PlyElement> elements;
    std::size_t bytes = 0;  ///< where the body starts
};

/// Reads the header (end_header within the first kMaxPlyHeader bytes, a known format, known
/// types, counts within the limits).
PlyHeader readPlyHeader(std::ifstream& in, std::uintmax_t fileSize, const std::string& path) {
    std::string text(std::min<std::uintmax_t>(fileSize, kMaxPlyHeader), '\0');
    in.read(text.data(), std::streamsize(text.size()));
    text.resize(std::size_t(in.gcount()));
    PlyHeader header;
    header.bytes = plyHeaderEnd(text, path);
    std::istringstream lines(text.substr(0, header.bytes));
    std::string line;
    while (std::getline(lines, line)) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        std::istringstream words(line);
        std::string word;
        words >> word;
        if (word == "format") {
            std::string& format = header.format;
            std::string version;
            words >> format >> version;
            if (format != "ascii" && format != "binary_little_endian" &&
                format != "binary_big_endian")
                refuse(path, "PLY format '" + format.substr(0, 40) + "' unknown");
        } else if (word == "element") {
            header.elements.push_back(readPlyElement(words, path));
        } else if (word == "property") {
            if (header.elements.empty()) refuse(path, "a PLY property before any element");
            header.elements.back().properties.push_back(readPlyProperty(words, path));
        }
    }
    if (header.format.empty()) refuse(path, "a PLY header without a format line");
    return header;
}

/// Reads list `p` of element `e`'s item `i`: its length (3 to kMaxFaceCorners for a face) and, for
/// a face, that each corner names one of the `vertices`.
void checkPlyList(PlyBody& body, const PlyElement& e, const PlyProperty& p, std::uint64_t i,
                  std::uint64_t vertices, const std::string& path) {
    const double n = body.count(p);
    const bool corners = e.name == "face";
    if (!(n >= 0) || n != std::floor(n) || (corners && (n < 3 || n > kMaxFaceCorners)))
        refuse(path,
               e.name + " " + std::to_string(i) + " has " + countText(n) + " items in its list '" +
                   p.name +
                   (corners ? "' (a face has 3 to " + std::to_string(kMaxFaceCorners) + " corners)"
                            : "'"));
    if (n > double(kMaxFaceCorners) * 16)
        refuse(path, e.name + " " + std::to_string(i) + "'s list '" + p.name + "' is longer than " +
                         std::to_string(kMaxFaceCorners * 16));
    for (int k = 0; k < int(n); ++k) {
        const double v = body.item(p);
        if (corners && !(v >= 0 && v < double(vertices)))
            refuse(path, "face " + std::to_string(i) + " names the vertex " + number(v) + " of " +
                             std::to_string(vertices));
    }
}

/// Skips a binary body's element without lists whole (only its size matters); false where the
/// element has a list or the body is ASCII, to be read value by value.
bool skippedWhole(std::ifstream& in, const PlyElement& e, bool binary, std::uintmax_t fileSize,
                  const std::string& path) {
    bool fixed = true;
    std::uint64_t bytes = 0;
    for (const PlyProperty& p : e.properties) fixed &= p.countSize == 0, bytes += p.size;
    if (!binary || !fixed) return false;
    const std::uintmax_t at = std::uintmax_t(in.tellg());
    if (e.count * bytes > fileSize - std::min(fileSize, at))
        refuse(path, "the binary PLY body ends before the " + std::to_string(e.count) + " " +
                         e.name + " elements its header announces");
    in.seekg(std::streamoff(e.count * bytes), std::ios::cur);
    return true;
}

/// Walks a PLY file: its header and its body (every element there, list lengths and a face's
/// vertex indices within range, nothing missing).
void checkPly(const std::string& path, std::uintmax_t fileSize) {
    std::ifstream in(path, std::ios::binary);
    if (!in) refuse(path, std::strerror(errno));
    const PlyHeader header = readPlyHeader(in, fileSize, path);
    std::uint64_t vertices = 0;
    for (const PlyElement& e : header.elements)
        if (e.name == "vertex") vertices = e.count;
    in.clear();
    in.seekg(std::streamoff(header.bytes));
    PlyBody body(in, header.format, path);
    for (const PlyElement& e : header.elements) {
        if (skippedWhole(in, e, body.binary(), fileSize, path)) continue;
        for (std::uint64_t i = 0; i < e.count; ++i)
            for (const PlyProperty& p : e.properties) {
                if (p.countSize == 0)
                    body.item(p);
                else
                    checkPlyList(body, e, p, i, vertices, path);
            }
    }
}

/// Whether assimp would take the file for PLY: the first three letters, after blank lines, are
/// "ply" in either case (it hangs on some such files that are not PLY, so these are walked).
bool looksLikePly(const char* head, std::size_t got, std::size_t& lead) {
    lead = 0;
    while (lead < got && std::isspace(static_cast<unsigned char>(head[lead]))) ++lead;
    bool ply = got >= lead + 3;
    for (std::size_t k = 0; k < 3 && lead + k < got; ++k)
        ply &= std::tolower(static_cast<unsigned char>(head[lead + k])) == "ply"[k];
    return ply;
}

/// Whether an ASCII STL names a facet somewhere, read in chunks from the start.
bool hasFacet(std::ifstream& in) {
    in.clear();
    in.seekg(0);
    std::string chunk(1 << 16, '\0'), tail;
    while (in.read(chunk.data(), std::streamsize(chunk.size())) || in.gcount() > 0) {
        const std::string text = tail + chunk.substr(0, std::size_t(in.gcount()));
        if (text.find("facet") != std::string::npos) return true;
        tail = text.substr(text.size() - std::min<std::size_t>(text.size(), 4));
    }
    return false;
}

/// STL: binary is 84 + 50 n bytes for n triangles (assimp's test too); ASCII starts "solid".
void checkStl(const std::string& path, std::ifstream& in, const char* head, std::size_t got,
              std::uintmax_t size) {
    std::uint32_t n = 0;
    if (got == 84) std::memcpy(&n, head + 80, 4);  // little-endian, as the format is
    if (got == 84 && size == 84 + 50 * std::uintmax_t(n)) return;
    std::size_t first = 0;
    while (first < got && std::isspace(static_cast<unsigned char>(head[first]))) ++first;
    if (got - first >= 5 && std::memcmp(head + first, "solid", 5) == 0) {
        // An ASCII STL without a facet: assimp's answer ("orphaned meshes") would not say so.
        if (hasFacet(in)) return;
        throw GeometryError(path +
                            ": the file holds no triangles (an ASCII STL without a "
                            "facet): give a surface mesh of triangles");
    }
    refuse(path, got == 84 ? "neither an ASCII STL (it does not start with 'solid') nor a binary "
                             "STL (its 84 + 50 x " +
                                 std::to_string(n) +
                                 " triangles = " + std::to_string(84 + 50 * std::uintmax_t(n)) +
                                 " bytes, the file " + std::to_string(size) + ")"
                           : "an STL file of " + std::to_string(size) + " bytes, too short");
}

}  // namespace

void checkMeshFile(const std::string& path) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) refuse(path, std::strerror(errno));
    if (!S_ISREG(st.st_mode))
        refuse(path, S_ISDIR(st.st_mode) ? "a directory"
                                         : "not a regular file (a FIFO, a device or a socket)");
    const std::uintmax_t size = std::uintmax_t(st.st_size);
    if (size == 0) refuse(path, "an empty file");
    if (size > kMaxMeshFileBytes)
        refuse(path, std::to_string(size >> 20) + " MiB, more than the " +
                         std::to_string(kMaxMeshFileBytes >> 20) + " MiB a mesh file may hold");
    std::ifstream in(path, std::ios::binary);
    char head[84] = {};
    in.read(head, sizeof head);
    if (!in && in.gcount() == 0) refuse(path, std::strerror(errno));
    const std::size_t got = std::size_t(in.gcount());
    std::size_t lead = 0;
    if (looksLikePly(head, got, lead)) {
        if (lead > 0 || got < 4 || std::memcmp(head, "ply", 3) != 0 ||
            (head[3] != '\n' && head[3] != '\r'))
            refuse(path, "a PLY file whose first line is not 'ply'");
        in.close();
        checkPly(path, size);
        return;
    }
    std::string ext = std::filesystem::path(path).extension().string();
    for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    if (ext == ".stl") checkStl(path, in, head, got, size);
}

}  // namespace num::geometry
