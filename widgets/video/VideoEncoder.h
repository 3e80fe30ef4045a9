#pragma once
// Writes a video file with Debian's FFmpeg libraries (libavformat, libavcodec, libswscale): MP4
// (H.264), WebM (VP9) or GIF, chosen by the file's extension. The file is written atomically: frames
// go to a temporary file beside the target, which replaces the target only when finish() succeeds;
// a failure or cancel() leaves the user's previous file as it was (issue 22, item 5).
//
//     VideoEncoder encoder;
//     if (!encoder.open("shot.mp4", QSize(1280, 720), 30.0, &error)) ...
//     for (...) encoder.addFrame(image, &error);
//     encoder.finish(&error);          // or cancel()

#include <QImage>
#include <QSize>
#include <QString>

#include <memory>

namespace cuelab {

enum class VideoFormat { Mp4, WebM, Gif };

// The format of a file name by its extension (case-insensitive .mp4, .webm, .gif); false otherwise.
bool videoFormatOf(const QString& path, VideoFormat* format);

// The frame rate a format really plays at for the asked one (frames/s): a GIF's frame delays are in
// hundredths of a second, so 30 becomes 100/3 = 33.3; MP4 and WebM keep it.
double playedFrameRate(VideoFormat format, double fps);

// The frame size a format can take: H.264 and VP9 in 4:2:0 need even widths and heights.
QSize encodableSize(VideoFormat format, QSize size);

class VideoEncoder {
public:
    VideoEncoder();
    ~VideoEncoder();  // cancels an unfinished file
    VideoEncoder(const VideoEncoder&) = delete;
    VideoEncoder& operator=(const VideoEncoder&) = delete;

    // Starts a video of frames of `size` (see encodableSize) at `fps` frames per second (see
    // playedFrameRate). False with a message naming the file when it cannot.
    bool open(const QString& path, QSize size, double fps, QString* error);
    // Adds the next frame (any QImage format; scaled if its size differs).
    bool addFrame(const QImage& frame, QString* error);
    // Flushes the encoder, writes the file's index and puts the file in place.
    bool finish(QString* error);
    // Drops the temporary file; the target is untouched.
    void cancel();

    int framesWritten() const;

private:
    struct Impl;
    std::unique_ptr<Impl> d_;
};

}  // namespace cuelab
