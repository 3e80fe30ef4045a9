#pragma once
// The 256 colours of a GIF video (issue 22, item 5) and the mapping of a frame onto them. One palette
// for the whole video, made from its first frame (the cloth, the rails and the balls are all there at
// t = 0), so that colours do not flicker from frame to frame. No dithering: a pixel's colour is its
// nearest palette colour, exactly, which the tests rely on.

#include <QImage>
#include <QVector>

#include <cstdint>
#include <vector>

namespace cuelab {

class GifPalette {
public:
    // The most frequent colours of `image` at 5 bits per channel (in order of frequency, ties by
    // colour), filled up with a coarse colour cube so that a colour first seen later has a near match.
    static GifPalette fromImage(const QImage& image);

    // A palette of the given colours (up to 256; a GIF read back gives its own).
    static GifPalette fromColours(const QVector<QRgb>& colours);

    const QVector<QRgb>& colours() const { return colours_; }  // 256, opaque
    // The palette index nearest to a colour (sum of squared channel differences at 5 bits per
    // channel; the first of equals).
    std::uint8_t indexOf(QRgb colour) const { return lookup_[key(colour)]; }
    // The frame as palette indices (Format_Indexed8 with this palette's colours).
    QImage quantize(const QImage& image) const;

private:
    static int key(QRgb c) { return ((qRed(c) >> 3) << 10) | ((qGreen(c) >> 3) << 5) | (qBlue(c) >> 3); }
    void buildLookup();

    QVector<QRgb> colours_;
    std::vector<std::uint8_t> lookup_;  // 32768 entries, one per 5-5-5 colour
};

}  // namespace cuelab
