#!/usr/bin/env python3
"""Extracts the code blocks of docs/extending.md for the tests that compile and run them.

Every fenced block must carry one of these info strings (else this script fails):
  cpp               a complete translation unit (a listing, a program or a plugin's source);
  cpp statements    statements, compiled in a function template instantiated for 2D and 3D
                    with `derivatives` (of Dim), `settings` and a `Storage<2> storage` in scope;
  cpp declarations  declarations, compiled in a namespace that uses num::sph;
  cpp plugin        the plugin walkthrough's source (also a complete translation unit);
  cmake plugin, json plugin   the walkthrough's CMakeLists.txt and scene, used by the plugin
                    consumer test (tests/consumer/build_plugin_consumer.cmake);
  sh                shell commands of the walkthrough (run by that test in its own words).
Usage: extract_blocks.py DOC OUT_DIR. Writes OUT_DIR/block_NN.cpp (one per C++ block),
OUT_DIR/blocks.txt (their list) and OUT_DIR/plugin/{damping.cpp,CMakeLists.txt,damped.json}.
"""
import os
import sys

PRELUDE = """#include "heat_diffusion.hpp"
#include "app/plugin.hpp"
#include "numerics.hpp"
#include "sph/fluid_model.hpp"
#include "spring_force.hpp"
"""

STATEMENTS = PRELUDE + """// A snippet may show a variable it does not use.
#pragma GCC diagnostic ignored "-Wunused-variable"
#pragma GCC diagnostic ignored "-Wunused-but-set-variable"
namespace docblock {{
using namespace num::sph;
template <int Dim>
[[maybe_unused]] void block([[maybe_unused]] DerivativeHolder<Dim>& derivatives,
                            [[maybe_unused]] const RunSettings& settings,
                            [[maybe_unused]] Storage<2>& storage) {{
#line {line} "{doc}"
{code}
}}
template void block<2>(DerivativeHolder<2>&, const RunSettings&, Storage<2>&);
template void block<3>(DerivativeHolder<3>&, const RunSettings&, Storage<2>&);
}}  // namespace docblock
"""

DECLARATIONS = PRELUDE + """namespace docblock {{
using namespace num::sph;
#line {line} "{doc}"
{code}
}}  // namespace docblock
"""

PLUGIN_FILES = {"cpp plugin": "damping.cpp", "cmake plugin": "CMakeLists.txt",
                "json plugin": "damped.json"}


def blocks(path):
    """(info string, first code line number, code) of every fenced block."""
    with open(path) as f:
        lines = f.read().split("\n")
    out, k = [], 0
    while k < len(lines):
        if lines[k].startswith("```"):
            info, start, k = lines[k][3:].strip(), k + 2, k + 1
            code = []
            while k < len(lines) and not lines[k].startswith("```"):
                code.append(lines[k])
                k += 1
            if k == len(lines):
                sys.exit(f"{path}:{start - 1}: a code block that is never closed")
            out.append((info, start, "\n".join(code) + "\n"))
        k += 1
    return out


def main():
    doc, out = sys.argv[1], sys.argv[2]
    os.makedirs(os.path.join(out, "plugin"), exist_ok=True)
    written, plugin = [], set()
    for n, (info, line, code) in enumerate(blocks(doc)):
        where = f"{doc}:{line - 1}"
        name = os.path.join(out, f"block_{n:02d}.cpp")
        if info in ("cpp", "cpp plugin"):
            header = os.path.join(out, f"block_{n:02d}.hpp")
            with open(header, "w") as f:
                f.write(f'#line {line} "{doc}"\n{code}')
            text = f'#include "{os.path.basename(header)}"\n'
        elif info == "cpp statements":
            text = STATEMENTS.format(line=line, doc=doc, code=code)
        elif info == "cpp declarations":
            text = DECLARATIONS.format(line=line, doc=doc, code=code)
        elif info in PLUGIN_FILES or info == "sh":
            text = None
        else:
            sys.exit(f"{where}: a code block with the info string '{info}'; every block must be "
                     "one of: cpp, cpp statements, cpp declarations, cpp plugin, cmake plugin, "
                     "json plugin, sh (tests/docs/extract_blocks.py)")
        if info in PLUGIN_FILES:
            if info in plugin:
                sys.exit(f"{where}: a second '{info}' block")
            plugin.add(info)
            with open(os.path.join(out, "plugin", PLUGIN_FILES[info]), "w") as f:
                f.write(code)
        if text is not None:
            with open(name, "w") as f:
                f.write(text)
            written.append(name)
    if len(plugin) != len(PLUGIN_FILES):
        sys.exit(f"{doc}: the plugin walkthrough needs one block each of "
                 f"{', '.join(sorted(PLUGIN_FILES))}")
    with open(os.path.join(out, "blocks.txt"), "w") as f:
        f.write(";".join(written))


if __name__ == "__main__":
    main()
