// VerletList's candidate codec: a particle's candidates sorted, then stored as gaps of 7-bit bytes.
#pragma once

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace num::detail {

/// The static helpers with which VerletList (spatial/neighbour_list.hpp, whose file comment
/// describes the encoding) sorts each particle's candidates and stores them as gaps.
class VerletCodec {
  protected:
    using Index = std::uint32_t;
    using Slot = std::uint8_t;                          // 7 bits of a gap, and whether more follow
    static constexpr Index kMore = 0x80, kBits = 0x7f;  // the flag, the bits of the gap

    /// Calls g(j) for each candidate decoded from the slots [b, e), which follow candidate j.
    /// The one-byte gaps first: in 2D a particle has two or three longer ones (the jumps between
    /// rows of cells), so the branch is seldom taken (a decoder without a branch, each byte put
    /// and kept only where its gap ends, made the gather loop take 5 % more time).
    template <class G>
    static void decode(Index j, const Slot* b, const Slot* e, G&& g) {
        for (const Slot* s = b; s < e; ++s) {
            Index gap = *s;
            if (gap & kMore) [[unlikely]] {  // a gap of 128 or more: its lower bits follow
                gap &= kBits;
                do gap = gap << 7 | (*++s & kBits);
                while (*s & kMore);
            }
            g(j += gap);  // one call site: g is inlined once
        }
    }

    /// Appends the gap from candidate `from` to `to` (to > from) to `out`, 7 bits per byte,
    /// the high ones first.
    static void encodeGap(Index from, Index to, std::vector<Slot>& out) {
        const Index gap = to - from;
        int shift = 0;
        while (shift + 7 < 32 && gap >> (shift + 7)) shift += 7;
        for (; shift > 0; shift -= 7) out.push_back(Slot(kMore | (gap >> shift & kBits)));
        out.push_back(Slot(gap & kBits));
    }

    /// Buffers of sortCandidates, one set per task of the build.
    struct SortBuffers {
        std::vector<std::uint64_t> bits;  // one bit per index of the candidates' range
        std::vector<Index> runs, merged;  // sortRuns' run bounds and its second buffer
    };
    /// A particle's candidates are sorted through a bitmap where their index range is at most
    /// this many indices per candidate (the bitmap then has at most one word per candidate).
    static constexpr std::size_t kBitmapSpan = 64;

    /// Sorts the candidates a[0, n) (distinct indices) into increasing order. Once the
    /// particles are ordered by cell, a particle's candidates lie within a few rows of cells in
    /// index: where their range is at most kBitmapSpan indices per candidate they are marked in a
    /// bitmap of that range and read back in order (at most four operations per candidate);
    /// otherwise (particles added since the last reordering come last, far away in index)
    /// sortRuns merges them.
    static void sortCandidates(Index* a, Index n, SortBuffers& buffers) {
        if (n < 2) return;
        Index lo = a[0], hi = a[0];
        for (Index k = 1; k < n; ++k) lo = std::min(lo, a[k]), hi = std::max(hi, a[k]);
        const std::size_t span = std::size_t(hi - lo) + 1;
        if (span > kBitmapSpan * n) return sortRuns(a, n, buffers.runs, buffers.merged);
        std::vector<std::uint64_t>& bits = buffers.bits;
        bits.assign((span + 63) / 64, 0);
        for (Index k = 0; k < n; ++k)
            bits[(a[k] - lo) >> 6] |= std::uint64_t(1) << ((a[k] - lo) & 63);
        Index out = 0;
        for (std::size_t w = 0; w < bits.size(); ++w)
            for (std::uint64_t word = bits[w]; word != 0; word &= word - 1)
                a[out++] = lo + Index(64 * w + std::size_t(std::countr_zero(word)));
    }

    /// Sorts a[0, n) made of ascending runs, as the cell grid returns the candidates (cell by
    /// cell, each in increasing index; 9 cells in 2D, 125 in 3D), by merging neighbouring runs
    /// pairwise: log2(runs) passes over the candidates.
    static void sortRuns(Index* a, Index n, std::vector<Index>& runs, std::vector<Index>& scratch) {
        runs.clear();
        runs.push_back(0);
        for (Index k = 1; k < n; ++k)
            if (a[k] < a[k - 1]) runs.push_back(k);
        runs.push_back(n);  // runs[r] is where run r starts; the last entry is the end
        if (runs.size() <= 2) return;
        if (scratch.size() < n) scratch.resize(2 * std::size_t(n));
        Index *from = a, *to = scratch.data();
        while (runs.size() > 2) {
            std::size_t merged = 0;
            for (std::size_t r = 0; r + 1 < runs.size(); r += 2) {
                const Index begin = runs[r], middle = runs[r + 1];
                const Index end = r + 2 < runs.size() ? runs[r + 2] : middle;
                std::merge(from + begin, from + middle, from + middle, from + end, to + begin);
                runs[merged++] = begin;
            }
            runs[merged++] = n;
            runs.resize(merged);
            std::swap(from, to);
        }
        if (from != a) std::copy(from, from + n, a);
    }
};

}  // namespace num::detail
