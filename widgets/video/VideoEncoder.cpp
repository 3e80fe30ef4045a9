#include "VideoEncoder.h"

#include "GifPalette.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QTemporaryFile>

#include <cmath>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <optional>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/log.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

namespace cuelab {

namespace {

QString avError(int code)
{
    char text[AV_ERROR_MAX_STRING_SIZE] = {};
    av_strerror(code, text, sizeof text);
    return QString::fromUtf8(text);
}

// The encoders Debian's libavcodec 5.1 provides for each format, the first one found being used.
const AVCodec* encoderFor(VideoFormat format)
{
    switch (format) {
    case VideoFormat::Mp4:
        if (const AVCodec* c = avcodec_find_encoder_by_name("libx264")) return c;
        return avcodec_find_encoder(AV_CODEC_ID_MPEG4);
    case VideoFormat::WebM:
        if (const AVCodec* c = avcodec_find_encoder_by_name("libvpx-vp9")) return c;
        return avcodec_find_encoder_by_name("libvpx");
    case VideoFormat::Gif: return avcodec_find_encoder(AV_CODEC_ID_GIF);
    }
    return nullptr;
}

const char* muxerName(VideoFormat format)
{
    switch (format) {
    case VideoFormat::Mp4: return "mp4";
    case VideoFormat::WebM: return "webm";
    case VideoFormat::Gif: return "gif";
    }
    return "mp4";
}

}  // namespace

bool videoFormatOf(const QString& path, VideoFormat* format)
{
    const QString suffix = QFileInfo(path).suffix().toLower();
    if (suffix == QLatin1String("mp4")) *format = VideoFormat::Mp4;
    else if (suffix == QLatin1String("webm")) *format = VideoFormat::WebM;
    else if (suffix == QLatin1String("gif")) *format = VideoFormat::Gif;
    else return false;
    return true;
}

double playedFrameRate(VideoFormat format, double fps)
{
    if (format != VideoFormat::Gif) return fps;
    const double centiseconds = std::max(2.0, std::round(100.0 / fps));  // browsers slow delays below 2 cs
    return 100.0 / centiseconds;
}

QSize encodableSize(VideoFormat format, QSize size)
{
    if (format == VideoFormat::Gif) return size;
    return QSize(size.width() & ~1, size.height() & ~1);
}

struct VideoEncoder::Impl {
    VideoFormat format = VideoFormat::Mp4;
    QString path;   // the target
    QString temp;   // where the frames go until finish()
    QSize size;
    AVFormatContext* muxer = nullptr;
    AVCodecContext* codec = nullptr;
    AVStream* stream = nullptr;
    SwsContext* scaler = nullptr;
    AVFrame* frame = nullptr;
    AVPacket* packet = nullptr;
    std::optional<GifPalette> palette;
    std::int64_t pts = 0;
    std::int64_t ptsStep = 1;  // in the codec's time base
    int frames = 0;
    bool headerWritten = false;

    ~Impl() { discard(); }

    void freeAll()
    {
        if (muxer) {
            if (muxer->pb) avio_closep(&muxer->pb);
            avformat_free_context(muxer);
            muxer = nullptr;
        }
        avcodec_free_context(&codec);
        sws_freeContext(scaler);
        scaler = nullptr;
        av_frame_free(&frame);
        av_packet_free(&packet);
    }
    void discard()
    {
        freeAll();
        if (!temp.isEmpty()) QFile::remove(temp);
        temp.clear();
    }
    bool fail(QString* error, const QString& message)
    {
        if (error) *error = QStringLiteral("%1: %2").arg(QFileInfo(path).fileName(), message);
        discard();
        return false;
    }
    // Sends a frame (null: the end) and writes every packet the encoder has ready.
    int send(AVFrame* f)
    {
        int status = avcodec_send_frame(codec, f);
        if (status < 0) return status;
        while ((status = avcodec_receive_packet(codec, packet)) >= 0) {
            packet->duration = ptsStep;
            av_packet_rescale_ts(packet, codec->time_base, stream->time_base);
            packet->stream_index = stream->index;
            status = av_interleaved_write_frame(muxer, packet);
            av_packet_unref(packet);
            if (status < 0) return status;
        }
        return status == AVERROR(EAGAIN) || status == AVERROR_EOF ? 0 : status;
    }
};

VideoEncoder::VideoEncoder() : d_(std::make_unique<Impl>()) {}
VideoEncoder::~VideoEncoder() = default;

int VideoEncoder::framesWritten() const { return d_->frames; }

bool VideoEncoder::open(const QString& path, QSize size, double fps, QString* error)
{
    // FFmpeg's own chatter (x264's statistics) is not for the user; real errors come back as codes.
    av_log_set_level(AV_LOG_ERROR);
    d_ = std::make_unique<Impl>();  // the old one's temporary file, if any, goes with it
    d_->path = path;
    if (!videoFormatOf(path, &d_->format))
        return d_->fail(error, QStringLiteral("not a video file name (expected .mp4, .webm or .gif)"));
    Impl& d = *d_;
    d.size = encodableSize(d.format, size);
    if (d.size.width() < 16 || d.size.height() < 16) return d.fail(error, QStringLiteral("the frames are too small"));
    if (!(fps > 0.0) || fps > 240.0) return d.fail(error, QStringLiteral("the frame rate must be above 0 and at most 240 frames/s"));
    // The temporary file beside the target (same file system: the final rename is atomic).
    const QFileInfo target(path);
    QTemporaryFile temp(target.absoluteDir().filePath(QStringLiteral(".%1.XXXXXX.part").arg(target.fileName())));
    temp.setAutoRemove(false);
    if (!temp.open()) return d.fail(error, QStringLiteral("cannot write in %1 (%2)").arg(target.absolutePath(), temp.errorString()));
    d.temp = temp.fileName();
    temp.close();

    const AVCodec* encoder = encoderFor(d.format);
    if (!encoder) return d.fail(error, QStringLiteral("this FFmpeg has no encoder for the format"));
    if (avformat_alloc_output_context2(&d.muxer, nullptr, muxerName(d.format), nullptr) < 0 || !d.muxer)
        return d.fail(error, QStringLiteral("this FFmpeg cannot write the format"));
    d.codec = avcodec_alloc_context3(encoder);
    d.frame = av_frame_alloc();
    d.packet = av_packet_alloc();
    if (!d.codec || !d.frame || !d.packet) return d.fail(error, QStringLiteral("out of memory"));
    d.codec->width = d.size.width();
    d.codec->height = d.size.height();
    if (d.format == VideoFormat::Gif) {
        // GIF delays are whole hundredths of a second.
        d.codec->time_base = AVRational{1, 100};
        d.ptsStep = static_cast<std::int64_t>(std::lround(100.0 / playedFrameRate(d.format, fps)));
        d.codec->pix_fmt = AV_PIX_FMT_PAL8;
    } else {
        const AVRational rate = av_d2q(fps, 100000);
        d.codec->time_base = av_inv_q(rate);
        d.codec->framerate = rate;
        d.codec->pix_fmt = AV_PIX_FMT_YUV420P;
        d.codec->gop_size = 60;
    }
    if (d.format == VideoFormat::Mp4) {
        av_opt_set(d.codec->priv_data, "preset", "veryfast", 0);
        av_opt_set(d.codec->priv_data, "crf", "18", 0);  // visually lossless for a rendered scene
    } else if (d.format == VideoFormat::WebM) {
        d.codec->bit_rate = 0;  // constant quality
        av_opt_set(d.codec->priv_data, "crf", "24", 0);
        av_opt_set(d.codec->priv_data, "deadline", "realtime", 0);
        av_opt_set(d.codec->priv_data, "cpu-used", "8", 0);
        av_opt_set(d.codec->priv_data, "row-mt", "1", 0);
    }
    if (d.muxer->oformat->flags & AVFMT_GLOBALHEADER) d.codec->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
    int status = avcodec_open2(d.codec, encoder, nullptr);
    if (status < 0) return d.fail(error, QStringLiteral("cannot start the encoder (%1)").arg(avError(status)));
    d.stream = avformat_new_stream(d.muxer, nullptr);
    if (!d.stream) return d.fail(error, QStringLiteral("out of memory"));
    d.stream->time_base = d.codec->time_base;
    avcodec_parameters_from_context(d.stream->codecpar, d.codec);
    status = avio_open(&d.muxer->pb, QFile::encodeName(d.temp).constData(), AVIO_FLAG_WRITE);
    if (status < 0) return d.fail(error, QStringLiteral("cannot write (%1)").arg(avError(status)));
    status = avformat_write_header(d.muxer, nullptr);
    if (status < 0) return d.fail(error, QStringLiteral("cannot write the header (%1)").arg(avError(status)));
    d.headerWritten = true;
    d.frame->format = d.codec->pix_fmt;
    d.frame->width = d.size.width();
    d.frame->height = d.size.height();
    if (av_frame_get_buffer(d.frame, 0) < 0) return d.fail(error, QStringLiteral("out of memory"));
    return true;
}

bool VideoEncoder::addFrame(const QImage& image, QString* error)
{
    Impl& d = *d_;
    if (!d.headerWritten) {
        if (error) *error = QStringLiteral("the video is not open");
        return false;
    }
    QImage rgb = image.convertToFormat(QImage::Format_RGB32);
    if (rgb.size() != d.size) rgb = rgb.scaled(d.size, Qt::IgnoreAspectRatio, Qt::SmoothTransformation);
    if (av_frame_make_writable(d.frame) < 0) return d.fail(error, QStringLiteral("out of memory"));
    if (d.format == VideoFormat::Gif) {
        if (!d.palette) d.palette = GifPalette::fromImage(rgb);
        const QImage indexed = d.palette->quantize(rgb);
        for (int y = 0; y < d.size.height(); ++y)
            std::copy_n(indexed.constScanLine(y), d.size.width(), d.frame->data[0] + y * d.frame->linesize[0]);
        auto* colours = reinterpret_cast<std::uint32_t*>(d.frame->data[1]);
        for (int i = 0; i < 256; ++i) colours[i] = d.palette->colours()[i] | 0xff000000u;
    } else {
        // Qt's RGB32 is a native-endian 0xffRRGGBB word per pixel: FFmpeg's RGB32.
        d.scaler = sws_getCachedContext(d.scaler, d.size.width(), d.size.height(), AV_PIX_FMT_RGB32, d.size.width(),
                                        d.size.height(), AV_PIX_FMT_YUV420P, SWS_BICUBIC, nullptr, nullptr, nullptr);
        if (!d.scaler) return d.fail(error, QStringLiteral("cannot convert the frame's colours"));
        const uint8_t* planes[1] = {rgb.constBits()};
        const int strides[1] = {static_cast<int>(rgb.bytesPerLine())};
        sws_scale(d.scaler, planes, strides, 0, d.size.height(), d.frame->data, d.frame->linesize);
    }
    d.frame->pts = d.pts;
    d.pts += d.ptsStep;
    const int status = d.send(d.frame);
    if (status < 0) return d.fail(error, QStringLiteral("cannot encode frame %1 (%2)").arg(d.frames + 1).arg(avError(status)));
    ++d.frames;
    return true;
}

bool VideoEncoder::finish(QString* error)
{
    Impl& d = *d_;
    if (!d.headerWritten) {
        if (error) *error = QStringLiteral("the video is not open");
        return false;
    }
    if (d.frames == 0) return d.fail(error, QStringLiteral("a video needs at least one frame"));
    int status = d.send(nullptr);
    if (status < 0) return d.fail(error, QStringLiteral("cannot finish the encoding (%1)").arg(avError(status)));
    status = av_write_trailer(d.muxer);
    if (status < 0) return d.fail(error, QStringLiteral("cannot write the end of the file (%1)").arg(avError(status)));
    status = avio_closep(&d.muxer->pb);
    if (status < 0) return d.fail(error, QStringLiteral("cannot write (%1)").arg(avError(status)));
    // The temporary file was made private (0600); the video gets the old file's permissions, or a
    // new file's usual ones.
    const QFileInfo old(d.path);
    QFile::setPermissions(d.temp, old.exists() ? old.permissions()
                                               : QFile::ReadOwner | QFile::WriteOwner | QFile::ReadGroup | QFile::ReadOther);
    // rename(2) replaces the target in one step: a reader sees the old video or the new one.
    if (std::rename(QFile::encodeName(d.temp).constData(), QFile::encodeName(d.path).constData()) != 0)
        return d.fail(error, QStringLiteral("cannot put the video in place (%1)").arg(QString::fromLocal8Bit(std::strerror(errno))));
    d.temp.clear();
    d.freeAll();
    d.headerWritten = false;
    return true;
}

void VideoEncoder::cancel()
{
    d_->discard();
    d_->headerWritten = false;
}

}  // namespace cuelab
