#pragma once
// Reads a video file back with libavformat and libavcodec, for the tests: every frame decoded to an
// RGB32 image (GIF frames through their own palette), and the duration from the packets' own times.

#include <QImage>
#include <QString>

#include <vector>

namespace cuelab::test {

struct DecodedVideo {
    std::vector<QImage> frames;  // in order, RGB32
    double duration = 0.0;       // s: the end of the last packet (its time plus its duration)
    QString codec;               // the decoder's name ("h264", "vp9", "gif")
    std::vector<QRgb> palette;   // a GIF's global colour table, read from the file itself; empty otherwise
    double containerDuration = 0.0;  // s, as the container's header says (0 when it says nothing)
    QString error;               // set when the file could not be read
};

DecodedVideo decodeVideo(const QString& path);

}  // namespace cuelab::test
