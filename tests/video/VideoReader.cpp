#include "VideoReader.h"

#include <QFile>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libswscale/swscale.h>
}

#include <algorithm>

namespace cuelab::test {

namespace {

QImage toImage(const AVFrame* frame, SwsContext** scaler, std::vector<QRgb>* firstPalette)
{
    QImage image(frame->width, frame->height, QImage::Format_RGB32);
    if (frame->format == AV_PIX_FMT_PAL8) {
        const auto* palette = reinterpret_cast<const std::uint32_t*>(frame->data[1]);
        if (firstPalette->empty())
            for (int i = 0; i < 256; ++i) firstPalette->push_back(palette[i] | 0xff000000u);
        for (int y = 0; y < frame->height; ++y) {
            auto* line = reinterpret_cast<QRgb*>(image.scanLine(y));
            const uint8_t* in = frame->data[0] + y * frame->linesize[0];
            for (int x = 0; x < frame->width; ++x) line[x] = palette[in[x]] | 0xff000000u;
        }
        return image;
    }
    *scaler = sws_getCachedContext(*scaler, frame->width, frame->height, AVPixelFormat(frame->format), frame->width,
                                   frame->height, AV_PIX_FMT_RGB32, SWS_BICUBIC, nullptr, nullptr, nullptr);
    uint8_t* planes[1] = {image.bits()};
    const int strides[1] = {static_cast<int>(image.bytesPerLine())};
    sws_scale(*scaler, frame->data, frame->linesize, 0, frame->height, planes, strides);
    // A GIF decodes to RGBA, transparent where nothing was ever drawn: compare the colours only.
    for (int y = 0; y < image.height(); ++y) {
        auto* line = reinterpret_cast<QRgb*>(image.scanLine(y));
        for (int x = 0; x < image.width(); ++x) line[x] |= 0xff000000u;
    }
    return image;
}

}  // namespace

DecodedVideo decodeVideo(const QString& path)
{
    DecodedVideo out;
    AVFormatContext* format = nullptr;
    if (avformat_open_input(&format, QFile::encodeName(path).constData(), nullptr, nullptr) < 0) {
        out.error = QStringLiteral("cannot open %1").arg(path);
        return out;
    }
    avformat_find_stream_info(format, nullptr);
    if (format->duration > 0) out.containerDuration = static_cast<double>(format->duration) / AV_TIME_BASE;
    const AVCodec* decoder = nullptr;
    const int stream = av_find_best_stream(format, AVMEDIA_TYPE_VIDEO, -1, -1, &decoder, 0);
    if (stream < 0 || !decoder) {
        out.error = QStringLiteral("no video stream in %1").arg(path);
        avformat_close_input(&format);
        return out;
    }
    AVCodecContext* codec = avcodec_alloc_context3(decoder);
    avcodec_parameters_to_context(codec, format->streams[stream]->codecpar);
    avcodec_open2(codec, decoder, nullptr);
    out.codec = QString::fromLatin1(decoder->name);
    const AVRational timeBase = format->streams[stream]->time_base;
    AVPacket* packet = av_packet_alloc();
    AVFrame* frame = av_frame_alloc();
    SwsContext* scaler = nullptr;
    const auto drain = [&] {
        while (avcodec_receive_frame(codec, frame) >= 0) {
            out.frames.push_back(toImage(frame, &scaler, &out.palette));
            av_frame_unref(frame);
        }
    };
    while (av_read_frame(format, packet) >= 0) {
        if (packet->stream_index == stream) {
            if (packet->pts != AV_NOPTS_VALUE)
                out.duration = std::max(out.duration, static_cast<double>(packet->pts + packet->duration) * av_q2d(timeBase));
            avcodec_send_packet(codec, packet);
            drain();
        }
        av_packet_unref(packet);
    }
    avcodec_send_packet(codec, nullptr);
    drain();
    sws_freeContext(scaler);
    av_frame_free(&frame);
    av_packet_free(&packet);
    avcodec_free_context(&codec);
    avformat_close_input(&format);
    // A GIF's global colour table (GIF89a: a 6-byte signature, then the logical screen descriptor,
    // whose packed byte's top bit says there is a table of 2^(n+1) RGB triplets right after it).
    QFile file(path);
    if (out.codec == QLatin1String("gif") && file.open(QIODevice::ReadOnly)) {
        const QByteArray head = file.read(13 + 3 * 256);
        if (head.size() >= 13 && (static_cast<unsigned char>(head[10]) & 0x80)) {
            const int colours = 1 << ((static_cast<unsigned char>(head[10]) & 7) + 1);
            for (int i = 0; i < colours && 13 + 3 * i + 2 < head.size(); ++i) {
                const auto at = [&head](int k) { return static_cast<unsigned char>(head[k]); };
                out.palette.push_back(qRgb(at(13 + 3 * i), at(14 + 3 * i), at(15 + 3 * i)));
            }
        }
    }
    return out;
}

}  // namespace cuelab::test
