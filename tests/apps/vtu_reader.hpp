// A reader of VTK XML UnstructuredGrid files with appended raw data (UInt64 block headers),
// written from the file format description independently of the writer in src/output: it parses
// the XML tags and the binary blocks and returns every DataArray as doubles.
#pragma once

#include <cstdint>
#include <cstring>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace apptest {

struct VtuArray {
    std::string type;
    int components = 1;
    std::vector<double> values;
};

struct VtuFile {
    std::size_t points = 0;
    double time = 0;
    std::map<std::string, VtuArray> arrays;  ///< PointData arrays and "Points"
};

namespace detail {
inline std::string attribute(const std::string& tag, const std::string& name) {
    const std::string key = " " + name + "=\"";
    const auto p = tag.find(key);
    if (p == std::string::npos) return "";
    const auto start = p + key.size();
    return tag.substr(start, tag.find('"', start) - start);
}
template <class T>
void decode(const char* data, std::size_t bytes, std::vector<double>& out) {
    for (std::size_t k = 0; k + sizeof(T) <= bytes; k += sizeof(T)) {
        T v;
        std::memcpy(&v, data + k, sizeof(T));
        out.push_back(double(v));
    }
}
}  // namespace detail

inline VtuFile readVtu(const std::string& text) {
    VtuFile f;
    const auto appended = text.find("<AppendedData");
    if (appended == std::string::npos) throw std::runtime_error("no AppendedData");
    if (detail::attribute(text.substr(0, text.find('>', text.find("<VTKFile"))), "header_type") !=
        "UInt64")
        throw std::runtime_error("header_type is not UInt64");
    const std::size_t base = text.find('_', text.find('>', appended)) + 1;
    const std::string xml = text.substr(0, appended);
    const auto piece = xml.find("<Piece");
    f.points = std::stoul(
        detail::attribute(xml.substr(piece, xml.find('>', piece) - piece), "NumberOfPoints"));
    const auto tv = xml.find("Name=\"TimeValue\"");
    if (tv != std::string::npos) f.time = std::stod(xml.substr(xml.find('>', tv) + 1));
    std::size_t pos = 0;
    while ((pos = xml.find("<DataArray", pos)) != std::string::npos) {
        const std::string tag = xml.substr(pos, xml.find('>', pos) - pos);
        pos += tag.size();
        if (detail::attribute(tag, "format") != "appended") continue;
        VtuArray a;
        a.type = detail::attribute(tag, "type");
        const std::string nc = detail::attribute(tag, "NumberOfComponents");
        a.components = nc.empty() ? 1 : std::stoi(nc);
        const std::size_t offset = base + std::stoull(detail::attribute(tag, "offset"));
        std::uint64_t bytes;
        std::memcpy(&bytes, text.data() + offset, 8);
        if (offset + 8 + bytes > text.size()) throw std::runtime_error("block past the end");
        const char* data = text.data() + offset + 8;
        if (a.type == "Float64")
            detail::decode<double>(data, bytes, a.values);
        else if (a.type == "Float32")
            detail::decode<float>(data, bytes, a.values);
        else if (a.type == "Int32")
            detail::decode<std::int32_t>(data, bytes, a.values);
        else if (a.type == "Int64")
            detail::decode<std::int64_t>(data, bytes, a.values);
        else if (a.type == "UInt8")
            detail::decode<std::uint8_t>(data, bytes, a.values);
        else
            throw std::runtime_error("unknown type " + a.type);
        f.arrays[detail::attribute(tag, "Name")] = std::move(a);
    }
    return f;
}

}  // namespace apptest
