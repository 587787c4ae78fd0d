#include "lightmap/chart_packing.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <tuple>

namespace rad {
namespace {

using Flat = std::array<glm::dvec2, 3>;

// Rows of bits, a spare word at the end of each so that a shifted row may spill into it.
class Bitmap {
public:
    Bitmap(std::uint32_t width, std::uint32_t height)
        : width_(width), height_(height), words_(width / 64 + 2), bits_(std::size_t{words_} * height, 0) {}

    std::uint32_t width() const { return width_; }
    std::uint32_t height() const { return height_; }
    std::uint32_t words() const { return words_; }
    const std::uint64_t* row(std::uint32_t y) const { return &bits_[std::size_t{y} * words_]; }
    std::uint64_t* row(std::uint32_t y) { return &bits_[std::size_t{y} * words_]; }
    bool get(std::uint32_t x, std::uint32_t y) const { return (row(y)[x >> 6] >> (x & 63)) & 1u; }
    void set(std::uint32_t x, std::uint32_t y) { row(y)[x >> 6] |= std::uint64_t{1} << (x & 63); }

    // The first set bit of row y at or after x (width() if none).
    std::uint32_t nextSet(std::uint32_t x, std::uint32_t y) const {
        const std::uint64_t* r = row(y);
        for (std::uint32_t k = x >> 6; k * 64 < width_; ++k) {
            std::uint64_t set = r[k];
            if (k == (x >> 6)) set &= ~std::uint64_t{0} << (x & 63);
            if (set != 0) return std::min(width_, k * 64 + static_cast<std::uint32_t>(__builtin_ctzll(set)));
        }
        return width_;
    }

    // The first clear bit of row y at or after x (width() if none).
    std::uint32_t nextClear(std::uint32_t x, std::uint32_t y) const {
        const std::uint64_t* r = row(y);
        for (std::uint32_t k = x >> 6; k * 64 < width_; ++k) {
            std::uint64_t clear = ~r[k];
            if (k == (x >> 6)) clear &= ~std::uint64_t{0} << (x & 63);
            if (clear != 0) return std::min(width_, k * 64 + static_cast<std::uint32_t>(__builtin_ctzll(clear)));
        }
        return width_;
    }

private:
    std::uint32_t width_, height_, words_;
    std::vector<std::uint64_t> bits_;
};

// A page: its bits, and per row the longest run of clear bits (what a claim's row needs), so
// that the search passes over rows too full for a claim without looking at them bit by bit.
struct Page {
    explicit Page(std::uint32_t side) : bits(side, side), longestClear(side, side) {}
    Bitmap bits;
    std::vector<std::uint32_t> longestClear;
    std::uint32_t rowsUsed = 0;  // rows down to the lowest claim's last

    void recount(std::uint32_t y) {
        std::uint32_t longest = 0, run = 0;
        const std::uint64_t* r = bits.row(y);
        for (std::uint32_t k = 0; k * 64 < bits.width(); ++k) {
            const std::uint32_t valid = std::min<std::uint32_t>(64, bits.width() - k * 64);
            const std::uint64_t word = r[k];
            if (word == 0) {
                run += valid;
                continue;
            }
            if (word == ~std::uint64_t{0} && valid == 64) {
                longest = std::max(longest, run);
                run = 0;
                continue;
            }
            for (std::uint32_t b = 0; b < valid; ++b)
                if ((word >> b) & 1u) {
                    longest = std::max(longest, run);
                    run = 0;
                } else {
                    ++run;
                }
        }
        longestClear[y] = std::max(longest, run);
    }
};

// Per row of a claim: its first set bit, the span from there to its last, whether every bit
// between is set (0, 0, true for an empty row), and its longest run of set bits, which a page's
// row must hold clear for the claim to lie across it.
struct RowShape {
    std::uint32_t first = 0, span = 0;
    bool solid = true;
    std::uint32_t longestRun = 0;
};

std::vector<RowShape> rowShapes(const Bitmap& claim) {
    std::vector<RowShape> shape(claim.height());
    for (std::uint32_t y = 0; y < claim.height(); ++y) {
        std::uint32_t first = claim.width(), last = 0, count = 0, run = 0, longest = 0;
        for (std::uint32_t x = 0; x < claim.width(); ++x) {
            if (!claim.get(x, y)) {
                run = 0;
                continue;
            }
            first = std::min(first, x), last = x, ++count;
            longest = std::max(longest, ++run);
        }
        if (first < claim.width()) shape[y] = {first, last - first + 1, count == last - first + 1, longest};
    }
    return shape;
}

// Whether `claim` placed with its corner at (x, y) of `page` meets a set bit there; or, with
// `place`, sets its bits there.
bool meets(const Bitmap& claim, Bitmap& page, std::uint32_t x, std::uint32_t y, bool place) {
    const std::uint32_t first = x >> 6, shift = x & 63;
    const std::uint32_t used = (claim.width() + 63) / 64;
    for (std::uint32_t r = 0; r < claim.height(); ++r) {
        const std::uint64_t* m = claim.row(r);
        std::uint64_t* p = page.row(y + r) + first;
        for (std::uint32_t k = 0; k <= used; ++k) {
            std::uint64_t bits = k < used ? m[k] << shift : 0;
            if (shift != 0 && k > 0) bits |= m[k - 1] >> (64 - shift);
            if (bits == 0) continue;
            if (place)
                p[k] |= bits;
            else if (p[k] & bits)
                return true;
        }
    }
    return false;
}

// The chart's claim: the texels its triangles touch, grown by `gutter` on every side; its
// corner stands for the chart's box's corner less the gutter. A chart that touches no texel (a
// point) claims the one at its corner.
Bitmap claimOf(const std::vector<Flat>& corners, std::uint32_t width, std::uint32_t height, std::uint32_t gutter) {
    Bitmap claim(width + 2 * gutter, height + 2 * gutter);
    Bitmap covered(width, height);
    bool any = false;
    for (const Flat& f : corners)
        for (const auto& [x, y] : touchedTexels(f))
            if (x >= 0 && y >= 0 && x < width && y < height) {
                covered.set(static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y));
                any = true;
            }
    if (!any) covered.set(0, 0);
    for (std::uint32_t y = 0; y < height; ++y)
        for (std::uint32_t x = 0; x < width; ++x)
            if (covered.get(x, y))
                for (std::uint32_t dy = 0; dy <= 2 * gutter; ++dy)
                    for (std::uint32_t dx = 0; dx <= 2 * gutter; ++dx) claim.set(x + dx, y + dy);
    return claim;
}

// A claim turned a quarter counter-clockwise, as packCharts turns its chart ((x, y) to
// (height - y, x)): texel (x, y) of a w x h claim to (h - 1 - y, x) of the h x w one (the
// gutter's dilation is the same square either way round, so this is the turned chart's claim).
Bitmap turnedClaim(const Bitmap& claim) {
    Bitmap out(claim.height(), claim.width());
    for (std::uint32_t y = 0; y < claim.height(); ++y)
        for (std::uint32_t x = claim.nextSet(0, y); x < claim.width(); x = claim.nextSet(x + 1, y))
            out.set(claim.height() - 1 - y, x);
    return out;
}

// The first corner, row by row, where the claim fits the page (inside it, meeting nothing).
// A row of the page whose longest clear run is shorter than the longest run any row of the claim
// needs rules out every corner that would put the claim across it; within a row, a solid row of
// the claim that meets a set bit rules out every corner up to the one that clears it.
bool firstFit(const Bitmap& claim, const std::vector<RowShape>& shape, const Page& page, std::uint32_t* atX,
              std::uint32_t* atY, std::uint32_t lastRow) {
    const std::uint32_t side = page.bits.width();
    if (claim.width() > side || claim.height() > side) return false;
    std::uint32_t narrowest = claim.width();
    bool solid = true;
    for (const RowShape& r : shape) {
        if (r.span > 0) narrowest = std::min(narrowest, r.longestRun);
        solid = solid && r.solid;
    }
    const std::uint32_t lastX = side - claim.width(), lastY = std::min(lastRow, side - claim.height());
    // The rows to test, widest first: they rule out the most corners.
    std::vector<std::uint32_t> rows;
    for (std::uint32_t r = 0; r < claim.height(); ++r)
        if (shape[r].span > 0) rows.push_back(r);
    std::stable_sort(rows.begin(), rows.end(),
                     [&](std::uint32_t a, std::uint32_t b) { return shape[a].span > shape[b].span; });
    for (std::uint32_t y = 0; y <= lastY; ++y) {
        bool possible = true;
        for (std::uint32_t r = claim.height(); r-- > 0;) {
            if (page.longestClear[y + r] >= shape[r].longestRun) continue;
            possible = false;
            if (page.longestClear[y + r] < narrowest) y += r;  // every corner up to here crosses it
            break;
        }
        if (!possible) continue;
        for (std::uint32_t x = 0; x <= lastX;) {
            std::uint32_t next = x;  // the least corner that may still fit
            for (std::size_t k = 0; k < rows.size() && next == x; ++k) {
                const std::uint32_t r = rows[k];
                const RowShape& row = shape[r];
                const std::uint32_t from = x + row.first;
                const std::uint32_t set = page.bits.nextSet(from, y + r);  // the first set bit from there
                if (row.solid ? set - from >= row.span : set > from) continue;
                // A set bit inside a solid row's span (or under a row's first bit): no corner fits
                // until the row's first bit comes to the next clear bit past it.
                next = page.bits.nextClear(set, y + r) - row.first;
            }
            if (next == x) {
                if (solid || !meets(claim, const_cast<Bitmap&>(page.bits), x, y, false)) {
                    *atX = x;
                    *atY = y;
                    return true;
                }
                next = x + 1;
            }
            x = next;
        }
    }
    return false;
}

}  // namespace

std::vector<std::array<std::int64_t, 2>> touchedTexels(const Flat& f) {
    std::vector<std::array<std::int64_t, 2>> out;
    double lo[2] = {std::min({f[0].x, f[1].x, f[2].x}), std::min({f[0].y, f[1].y, f[2].y})};
    double hi[2] = {std::max({f[0].x, f[1].x, f[2].x}), std::max({f[0].y, f[1].y, f[2].y})};
    const double twice = (f[1].x - f[0].x) * (f[2].y - f[0].y) - (f[2].x - f[0].x) * (f[1].y - f[0].y);
    if (!(std::fabs(twice) > 0.0) || !std::isfinite(twice)) return out;
    const double eps = 1e-9 * std::max({1.0, std::fabs(lo[0]), std::fabs(lo[1]), std::fabs(hi[0]), std::fabs(hi[1])});
    const auto x0 = static_cast<std::int64_t>(std::floor(lo[0])), x1 = static_cast<std::int64_t>(std::ceil(hi[0]));
    const auto y0 = static_cast<std::int64_t>(std::floor(lo[1])), y1 = static_cast<std::int64_t>(std::ceil(hi[1]));
    for (std::int64_t y = y0; y < y1; ++y)
        for (std::int64_t x = x0; x < x1; ++x) {
            // The box [x, x + 1] x [y, y + 1] against the triangle: the axes, then each edge's normal.
            if (!(hi[0] > x + eps && lo[0] < x + 1 - eps && hi[1] > y + eps && lo[1] < y + 1 - eps)) continue;
            bool apart = false;
            for (int e = 0; e < 3 && !apart; ++e) {
                const glm::dvec2 d = f[(e + 1) % 3] - f[e];
                const glm::dvec2 n(-d.y, d.x);
                const double length = std::hypot(n.x, n.y);
                double tLo = std::numeric_limits<double>::max(), tHi = -tLo, bLo = tLo, bHi = -tLo;
                for (const glm::dvec2& p : f) tLo = std::min(tLo, n.x * p.x + n.y * p.y), tHi = std::max(tHi, n.x * p.x + n.y * p.y);
                for (int c = 0; c < 4; ++c) {
                    const double v = n.x * (x + (c & 1)) + n.y * (y + (c >> 1));
                    bLo = std::min(bLo, v), bHi = std::max(bHi, v);
                }
                apart = std::min(tHi, bHi) - std::max(tLo, bLo) <= eps * length;
            }
            if (!apart) out.push_back({x, y});
        }
    return out;
}

std::vector<ChartPlacement> packChartTexels(const std::vector<ChartTexels>& charts, std::uint32_t pageSize,
                                            std::uint32_t gutter, std::uint32_t* pages, double* filled) {
    std::vector<ChartPlacement> placement(charts.size());
    // The longest box perimeter first, then in order: long thin charts, which fit few gaps, go in
    // while the page is open (on the engine model's atlas, about 4 points more of the page in
    // use than with the largest box area first).
    std::vector<std::uint32_t> order(charts.size());
    for (std::uint32_t c = 0; c < order.size(); ++c) order[c] = c;
    std::vector<std::uint64_t> key(charts.size());
    for (std::uint32_t c = 0; c < order.size(); ++c) key[c] = std::uint64_t{charts[c].width} + charts[c].height;
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
        return std::tie(key[b], a) < std::tie(key[a], b);
    });
    std::vector<Page> used;
    for (std::uint32_t c : order) {
        const ChartTexels& chart = charts[c];
        // The chart as it lies and turned one, two and three quarters: a concave chart may nest
        // into a gap one way round and not another.
        std::vector<Bitmap> claims;
        std::vector<std::vector<RowShape>> shapes;
        for (int turn = 0; turn < 4; ++turn) {
            claims.push_back(turn == 0 ? claimOf(chart.corners, chart.width, chart.height, gutter)
                                       : turnedClaim(claims.back()));
            shapes.push_back(rowShapes(claims.back()));
        }
        bool placed = false;
        for (std::uint32_t p = 0; !placed; ++p) {
            const bool fresh = p == used.size();
            if (fresh) used.emplace_back(pageSize);
            std::uint32_t best[2] = {0, 0};
            int which = -1;
            for (int turn = 0; turn < 4; ++turn) {
                std::uint32_t x = 0, y = 0;  // a later turn need not look below the best so far
                if (!firstFit(claims[turn], shapes[turn], used[p], &x, &y, which < 0 ? pageSize : best[1])) continue;
                if (which < 0 || std::tie(y, x) < std::tie(best[1], best[0])) best[0] = x, best[1] = y, which = turn;
            }
            if (which < 0) {
                if (fresh) throw std::invalid_argument("a lightmap chart larger than its page");
                continue;
            }
            meets(claims[which], used[p].bits, best[0], best[1], true);
            used[p].rowsUsed = std::max(used[p].rowsUsed, best[1] + claims[which].height());
            for (std::uint32_t r = 0; r < claims[which].height(); ++r) used[p].recount(best[1] + r);
            placement[c] = {p, best[0] + gutter, best[1] + gutter, static_cast<std::uint8_t>(which)};
            placed = true;
        }
    }
    *pages = static_cast<std::uint32_t>(used.size());
    if (filled != nullptr)
        *filled = used.empty() ? 0.0 : static_cast<double>(used.size() - 1) + double(used.back().rowsUsed) / pageSize;

    return placement;
}

}  // namespace rad
