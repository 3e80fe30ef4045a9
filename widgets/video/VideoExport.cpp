#include "VideoExport.h"

#include "VideoFrameRenderer.h"

#include <QTimer>

#include <algorithm>
#include <cmath>

namespace cuelab {

double VideoPlan::timeOf(int frame) const { return std::min(frame * step, endTime); }

VideoPlan planVideo(double endTime, VideoFormat format, double slow, double fps)
{
    VideoPlan plan;
    plan.playedFps = playedFrameRate(format, fps);
    plan.step = 1.0 / (plan.playedFps * slow);
    plan.endTime = std::max(endTime, 0.0);
    // Enough frames that the last one reaches the end (1e-9: an end on the grid is not a frame more).
    plan.frames = static_cast<int>(std::ceil(plan.endTime / plan.step - 1e-9)) + 1;
    return plan;
}

VideoExportJob::VideoExportJob(ViewScene scene, const SceneImageRenderer& look, const CameraPose& pose,
                               VideoRequest request, QObject* parent)
    : QObject(parent), scene_(std::move(scene)), request_(std::move(request))
{
    VideoFormat format = VideoFormat::Mp4;
    videoFormatOf(request_.path, &format);
    request_.size = encodableSize(format, request_.size);
    plan_ = planVideo(scene_.result ? scene_.result->endTime : 0.0, format, request_.slow, request_.fps);
    renderer_ = std::make_unique<VideoFrameRenderer>(scene_, look, pose, request_.size);
}

VideoExportJob::~VideoExportJob() = default;

bool VideoExportJob::begin(QString* error)
{
    next_ = 0;
    if (!(request_.slow >= 1.0 && request_.slow <= 1000.0)) {
        if (error) *error = QStringLiteral("the slow-motion factor must be between 1 and 1000");
        return false;
    }
    if (plan_.frames > 100000) {
        if (error) *error = QStringLiteral("the video would have %1 frames (at most 100000): lower --slow or --fps").arg(plan_.frames);
        return false;
    }
    return renderer_->initialize(error) && encoder_.open(request_.path, request_.size, request_.fps, error);
}

bool VideoExportJob::step(QString* error)
{
    const double t = plan_.timeOf(next_);
    QImage frame = renderer_->render(t);
    if (frame.isNull()) {
        if (error) *error = QStringLiteral("could not render the frame at %1 s").arg(t);
        encoder_.cancel();
        return false;
    }
    stampVideoTime(frame, t, request_.slow);
    if (!encoder_.addFrame(frame, error)) return false;
    ++next_;
    return true;
}

bool VideoExportJob::end(QString* error) { return encoder_.finish(error); }

bool VideoExportJob::run(QString* error)
{
    if (!begin(error)) return false;
    while (next_ < plan_.frames) {
        if (!step(error)) return false;
        emit progress(next_, plan_.frames);
    }
    return end(error);
}

void VideoExportJob::start()
{
    QString error;
    if (!begin(&error)) {
        encoder_.cancel();
        QTimer::singleShot(0, this, [this, error] { emit finished(false, error); });
        return;
    }
    running_ = true;
    QTimer::singleShot(0, this, &VideoExportJob::tick);
}

void VideoExportJob::tick()
{
    if (!running_) return;
    QString error;
    if (next_ < plan_.frames) {
        if (!step(&error)) {
            running_ = false;
            emit finished(false, error);
            return;
        }
        emit progress(next_, plan_.frames);
        QTimer::singleShot(0, this, &VideoExportJob::tick);
        return;
    }
    running_ = false;
    const bool ok = end(&error);
    emit finished(ok, error);
}

void VideoExportJob::cancel()
{
    if (!running_) return;
    running_ = false;
    encoder_.cancel();
    emit finished(false, QString());
}

}  // namespace cuelab
