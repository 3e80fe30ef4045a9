#pragma once
// A slow-motion video of a shot (issue 22, item 5): the scene as the view shows it (camera, overlays,
// layers, labels), sampled `slow` times slower than real time, each frame stamped with its time, and
// encoded with VideoEncoder. One job behind both surfaces: `cuelab --screenshot OUT.mp4` runs it to
// the end (run()), File > Export > Video runs it a frame per event-loop turn (start()), with progress
// and cancel, so that the window never freezes.

#include "VideoEncoder.h"
#include "view/OrbitCamera.h"
#include "view/Screenshot.h"
#include "view/ViewScene.h"

#include <QObject>
#include <QSize>
#include <QString>

#include <memory>

namespace cuelab {

class VideoFrameRenderer;

// Which frames a video holds. Frame k shows the shot at min(k · step, end): `step` is the simulated
// time between frames (1 / (played frame rate × slow)), and the last frame shows the end exactly.
struct VideoPlan {
    int frames = 0;
    double playedFps = 30.0;  // frames/s the file plays at (playedFrameRate)
    double step = 0.0;        // s of the shot per frame
    double endTime = 0.0;     // s, the shot's end
    double timeOf(int frame) const;
    double duration() const { return frames / playedFps; }  // s, the file's length
};

// The plan for a shot of `endTime` seconds; `slow` >= 1 (times slower), `fps` frames per second.
VideoPlan planVideo(double endTime, VideoFormat format, double slow, double fps);

struct VideoRequest {
    QString path;            // .mp4, .webm or .gif
    double slow = 1.0;       // times slower than real time, 1 to 1000
    double fps = 30.0;       // frames per second asked (a GIF plays at playedFrameRate)
    QSize size{1280, 720};   // pixels (encodableSize)
    // The camera: false, the view's own pose (its target, distance and turn); true, the whole table
    // from above, framed for the video's own aspect (the window's default: a video of a narrow view
    // is not a narrow video).
    bool frameTable = false;
};

class VideoExportJob : public QObject {
    Q_OBJECT
public:
    VideoExportJob(ViewScene scene, const SceneImageRenderer& look, const CameraPose& pose, VideoRequest request,
                   QObject* parent = nullptr);
    ~VideoExportJob() override;

    const VideoPlan& plan() const { return plan_; }
    const VideoRequest& request() const { return request_; }

    // Renders and encodes every frame now; false with *error when the video could not be made.
    bool run(QString* error);
    // The same, a frame per turn of the event loop; ends with finished().
    void start();
    // Stops a started job: the partial video is dropped and the previous file stays as it was.
    void cancel();
    bool isRunning() const { return running_; }

signals:
    void progress(int framesDone, int framesTotal);
    // ok: the file is in place; else `message` says why not ("" when cancelled).
    void finished(bool ok, const QString& message);

private:
    bool begin(QString* error);
    bool step(QString* error);  // the next frame; false on failure
    bool end(QString* error);
    void tick();

    ViewScene scene_;
    VideoRequest request_;
    VideoPlan plan_;
    std::unique_ptr<VideoFrameRenderer> renderer_;
    VideoEncoder encoder_;
    int next_ = 0;
    bool running_ = false;
};

}  // namespace cuelab
