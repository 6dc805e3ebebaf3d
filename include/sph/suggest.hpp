// Suggestions for misspelt names: the closest known name by edit distance.
#pragma once

#include <algorithm>
#include <string>
#include <vector>

namespace num::sph {

/// Levenshtein distance: insertions, deletions and substitutions turning a into b.
inline std::size_t editDistance(const std::string& a, const std::string& b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diag = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t up = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] != b[j - 1])});
            diag = up;
        }
    }
    return row[b.size()];
}

/// The candidate closest to `word` if it is close enough to be a likely misspelling (at most
/// max(2, |word| / 3) edits), else "".
inline std::string closestName(const std::string& word,
                               const std::vector<std::string>& candidates) {
    std::string best;
    std::size_t bestDistance = std::max<std::size_t>(2, word.size() / 3) + 1;
    for (const auto& c : candidates) {
        const std::size_t d = editDistance(word, c);
        if (d < bestDistance) bestDistance = d, best = c;
    }
    return best;
}

}  // namespace num::sph
