// A plugin library checked before dlopen (internal to numerics_app): dlopen maps the segments its
// headers name, so a truncated copy (an interrupted cp or download) ends the program with SIGBUS
// when they reach past the end of the file, and a library for another machine is reported by
// dlopen as a file it cannot open. These are found from the ELF headers and reported here.
#pragma once

#include <elf.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

namespace num::app::detail {

inline std::string machineName(unsigned machine) {
    switch (machine) {
        case EM_X86_64:
            return "x86-64";
        case EM_386:
            return "x86 (32-bit)";
        case EM_AARCH64:
            return "AArch64 (64-bit ARM)";
        case EM_ARM:
            return "ARM (32-bit)";
        case EM_PPC64:
            return "64-bit POWER";
        case EM_RISCV:
            return "RISC-V";
        case EM_S390:
            return "IBM Z";
        default:
            return "machine " + std::to_string(machine);
    }
}

/// The ELF identification and header of a file; false where it has none.
inline bool readElfHeader(const std::string& path, Elf64_Ehdr& h) {
    std::ifstream in(path, std::ios::binary);
    in.read(reinterpret_cast<char*>(&h), sizeof h);
    return in.gcount() == std::streamsize(sizeof h) && std::memcmp(h.e_ident, ELFMAG, SELFMAG) == 0;
}

/// What makes `path` unusable as a shared library of this program ("" when nothing does): not
/// ELF, another class, byte order or machine than this program's, not a shared object, or
/// shorter than its headers say (truncated).
inline std::string elfProblem(const std::string& path) {
    Elf64_Ehdr h{}, self{};
    if (!readElfHeader(path, h))
        return "it is not a shared library (no ELF header: a text file, an archive, or a "
               "truncated copy?)";
    const bool haveSelf = readElfHeader("/proc/self/exe", self);
    if (haveSelf && h.e_ident[EI_CLASS] != self.e_ident[EI_CLASS])
        return std::string("it is a ") + (h.e_ident[EI_CLASS] == ELFCLASS32 ? "32" : "64") +
               "-bit library and this program is " +
               (self.e_ident[EI_CLASS] == ELFCLASS32 ? "32" : "64") +
               "-bit: build the plugin for this machine";
    if (haveSelf && (h.e_ident[EI_DATA] != self.e_ident[EI_DATA] || h.e_machine != self.e_machine))
        return "it was built for " + machineName(h.e_machine) + ", this program runs on " +
               machineName(self.e_machine) + ": build the plugin on this machine";
    if (h.e_ident[EI_CLASS] != ELFCLASS64) return "";  // not this program's: dlopen reports it
    if (h.e_type != ET_DYN)
        return "it is an ELF file but not a shared library (build it with "
               "numerics_add_plugin, or add_library(... MODULE ...))";
    std::error_code ec;
    const auto size = std::filesystem::file_size(path, ec);
    if (ec) return "";
    // The furthest byte the headers name: the program headers, every segment, the sections.
    unsigned long long need = h.e_phoff + (unsigned long long)h.e_phnum * h.e_phentsize;
    if (h.e_shnum > 0)
        need = std::max(need, h.e_shoff + (unsigned long long)h.e_shnum * h.e_shentsize);
    if (h.e_phentsize == sizeof(Elf64_Phdr) && h.e_phoff + h.e_phnum * sizeof(Elf64_Phdr) <= size) {
        std::ifstream in(path, std::ios::binary);
        in.seekg(std::streamoff(h.e_phoff));
        for (int k = 0; k < h.e_phnum; ++k) {
            Elf64_Phdr p{};
            if (!in.read(reinterpret_cast<char*>(&p), sizeof p)) break;
            if (p.p_type == PT_LOAD)
                need = std::max<unsigned long long>(need, p.p_offset + p.p_filesz);
        }
    }
    if (need > size)
        return "the file is truncated (" + std::to_string(size) + " bytes, its headers describe " +
               std::to_string(need) + ": an interrupted copy?): copy or build it again";
    return "";
}

}  // namespace num::app::detail
