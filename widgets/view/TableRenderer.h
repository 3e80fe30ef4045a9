#pragma once
// Draws a ViewScene with OpenGL 3.3 core into the current framebuffer: the table mesh, instanced lit
// balls with their shadows, the cue stick, the overlay lines and the ghost balls. Shared by the
// TableView widget and the offscreen screenshot. The caller owns the context: initialize() and
// release() must run with it current, and release() before the context goes away.
//
// Per frame the renderer writes only the ball instances and the lines that depend on the current
// state (velocity, spin, selection) into buffers that keep their capacity: no allocation per frame.

#include "BallAppearance.h"
#include "BallOrientations.h"
#include "OverlayLines.h"
#include "ViewScene.h"

#include <QMatrix4x4>
#include <QOpenGLExtraFunctions>
#include <QSize>
#include <QString>
#include <QVector3D>

#include <bitset>
#include <memory>
#include <vector>

class QOpenGLFramebufferObject;
class QOpenGLShaderProgram;

namespace cuelab {

struct RenderFrame {
    QMatrix4x4 viewProjection;
    QVector3D eye;         // m
    QVector3D cameraUp;    // unit, the screen's up in the world
    float pixelAngle = 0;  // radians per pixel (vertical field of view / viewport height)
    QSize viewportPixels;  // framebuffer pixels
    double time = 0.0;     // s
    std::bitset<kOverlayCount> overlays;
    int selectedBall = -1;
    int highlightedEvent = -1;
};

// Radians per pixel of an image `heightPixels` high seen through the orbit camera.
float pixelAngle(int heightPixels);

class TableRenderer : protected QOpenGLExtraFunctions {
public:
    TableRenderer();
    ~TableRenderer();
    TableRenderer(const TableRenderer&) = delete;
    TableRenderer& operator=(const TableRenderer&) = delete;

    bool initialize(QString* error);  // compiles the shaders, creates buffers; context current
    void release();                   // frees every GL object; context current
    void setScene(const ViewScene& scene);
    void render(const RenderFrame& frame);

    // Whether the last frame drew the table without its cache (the camera had moved since the frame
    // before): the table was not antialiased, and one more frame with the same camera draws it so.
    bool tableUncached() const { return tableUncached_; }

    // The ball states of the last rendered frame (index = ball index).
    const std::vector<BallState>& states() const { return states_; }

private:
    struct LineBuffer {
        unsigned int vao = 0;
        unsigned int vbo = 0;
        std::size_t capacity = 0;  // vertices the buffer holds
        int count = 0;             // vertices to draw
    };

    void createLineBuffer(LineBuffer& buffer);
    void uploadLines(LineBuffer& buffer, const std::vector<LineVertex>& vertices);
    void drawLines(const LineBuffer& buffer, float widthPx, float pastAlpha,
                   float futureAlpha, float dashPeriod);
    void uploadTable();
    void drawTable(const RenderFrame& frame);
    bool tableCacheValid(const RenderFrame& frame, int samples, bool withCue) const;
    void buildTableCache(const RenderFrame& frame, int samples, bool withCue, unsigned int target);
    void drawCue(const RenderFrame& frame);
    void uploadSceneOverlays(int highlightedEvent);
    void updateBallInstances(const RenderFrame& frame);
    void createDigitTexture();

    ViewScene scene_;
    std::vector<BallLook> looks_;  // per ball
    BallOrientations orientations_;
    std::vector<BallState> states_;
    bool tableDirty_ = true;
    bool overlaysDirty_ = true;
    int overlaysHighlight_ = -1;  // the highlighted event the marker buffer was built for
    bool initialized_ = false;

    std::unique_ptr<QOpenGLShaderProgram> tableProgram_, tableCutProgram_, ballProgram_, ghostProgram_, shadowProgram_, lineProgram_;

    unsigned int tableVao_ = 0, tableVbo_ = 0;
    int tableCount_ = 0;
    int tableUncutCount_ = 0;  // vertices drawn without the pocket cut; the rest with it
    int tableGeneration_ = 0;  // counts table uploads

    // The table does not change while time runs or scrubs: it is drawn once into this framebuffer
    // (colour and depth) for a camera and copied into each frame until the camera or table changes.
    // For a single-sampled target it is drawn with kTableSamples into tableMultisampled_ and resolved
    // into the cache. While the camera moves (a new view every frame) the cache would be rebuilt each
    // frame for nothing: the table is then drawn straight into the frame, without multisampling.
    static constexpr int kTableSamples = 4;
    std::unique_ptr<QOpenGLFramebufferObject> tableCache_, tableMultisampled_;
    QMatrix4x4 cacheViewProjection_;
    int cacheSamples_ = -1;
    int cacheGeneration_ = -1;
    bool cacheHasCue_ = false;  // the cue stick is drawn into the cache before the shot
    QMatrix4x4 lastViewProjection_;  // the camera of the previous frame, to tell a moving camera
    bool hasLastFrame_ = false;
    bool tableUncached_ = false;
    unsigned int cueVao_ = 0, cueVbo_ = 0;
    int cueCount_ = 0;
    unsigned int ballVao_ = 0, ballInstanceVbo_ = 0;
    std::size_t ballCapacity_ = 0;
    int ballCount_ = 0;
    unsigned int ghostVao_ = 0, ghostInstanceVbo_ = 0;
    int ghostCount_ = 0;
    unsigned int shadowVao_ = 0, quadVbo_ = 0;  // the unit quad, shared by balls, ghosts and shadows
    unsigned int digitTexture_ = 0;

    LineBuffer pathLines_, markerLines_, ghostLines_, dynamicLines_;
    std::vector<LineVertex> scratchLines_;  // reused every frame
    std::vector<float> scratchInstances_;   // reused every frame
};

}  // namespace cuelab
