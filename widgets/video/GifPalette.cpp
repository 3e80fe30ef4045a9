#include "GifPalette.h"

#include <algorithm>
#include <array>
#include <limits>

namespace cuelab {

namespace {

QRgb centreOf(int key)
{
    // The centre of a 5-bit cell, as an 8-bit colour.
    const int r = ((key >> 10) & 31) * 8 + 4, g = ((key >> 5) & 31) * 8 + 4, b = (key & 31) * 8 + 4;
    return qRgb(r, g, b);
}

}  // namespace

GifPalette GifPalette::fromImage(const QImage& image)
{
    const QImage rgb = image.convertToFormat(QImage::Format_RGB32);
    std::vector<int> counts(32768, 0);
    for (int y = 0; y < rgb.height(); ++y) {
        const auto* line = reinterpret_cast<const QRgb*>(rgb.constScanLine(y));
        for (int x = 0; x < rgb.width(); ++x) ++counts[static_cast<std::size_t>(key(line[x]))];
    }
    std::vector<int> used;
    for (int k = 0; k < 32768; ++k)
        if (counts[static_cast<std::size_t>(k)] > 0) used.push_back(k);
    std::stable_sort(used.begin(), used.end(), [&counts](int a, int b) { return counts[std::size_t(a)] > counts[std::size_t(b)]; });
    GifPalette p;
    // 216 of the frame's own colours, then a 3x3x4 cube (36) for colours that appear later.
    constexpr int kOwn = 220;
    for (int k : used) {
        if (p.colours_.size() >= kOwn) break;
        p.colours_.push_back(centreOf(k));
    }
    for (int r = 0; r < 3; ++r)
        for (int g = 0; g < 3; ++g)
            for (int b = 0; b < 4; ++b) p.colours_.push_back(qRgb(r * 127, g * 127, b * 85));
    while (p.colours_.size() < 256) p.colours_.push_back(qRgb(0, 0, 0));
    p.colours_.resize(256);
    p.buildLookup();
    return p;
}

GifPalette GifPalette::fromColours(const QVector<QRgb>& colours)
{
    GifPalette p;
    p.colours_ = colours.mid(0, 256);
    if (p.colours_.isEmpty()) p.colours_.push_back(qRgb(0, 0, 0));
    p.buildLookup();
    return p;
}

void GifPalette::buildLookup()
{
    lookup_.assign(32768, 0);
    for (int k = 0; k < 32768; ++k) {
        const QRgb c = centreOf(k);
        int best = 0;
        int bestDistance = std::numeric_limits<int>::max();
        for (int i = 0; i < colours_.size(); ++i) {
            const QRgb p = colours_[i];
            const int dr = qRed(p) - qRed(c), dg = qGreen(p) - qGreen(c), db = qBlue(p) - qBlue(c);
            const int d = dr * dr + dg * dg + db * db;
            if (d < bestDistance) {
                bestDistance = d;
                best = i;
            }
        }
        lookup_[static_cast<std::size_t>(k)] = static_cast<std::uint8_t>(best);
    }
}

QImage GifPalette::quantize(const QImage& image) const
{
    const QImage rgb = image.convertToFormat(QImage::Format_RGB32);
    QImage out(rgb.size(), QImage::Format_Indexed8);
    out.setColorTable(colours_);
    for (int y = 0; y < rgb.height(); ++y) {
        const auto* in = reinterpret_cast<const QRgb*>(rgb.constScanLine(y));
        uchar* line = out.scanLine(y);
        for (int x = 0; x < rgb.width(); ++x) line[x] = indexOf(in[x]);
    }
    return out;
}

}  // namespace cuelab
