#pragma once
// The table pass: the cloth, cushions, jaws, pocket holes, rails (and the cue stick before the shot),
// drawn once per camera into a cached framebuffer and copied into every frame while only time runs.
// A pass of TableRenderer: context current in every call.
//
// The table does not change while time runs or scrubs: it is drawn once into the cache (colour and
// depth) for a camera and copied into each frame until the camera, the table or the cue changes. For
// a single-sampled target it is drawn with kTableSamples into a multisampled buffer and resolved into
// the cache. While the camera moves (a new view every frame) the cache would be rebuilt each frame for
// nothing: the table is then drawn straight into the frame, without multisampling.

#include "GlResources.h"
#include "RenderFrame.h"
#include "ShaderLibrary.h"
#include "Table.h"

#include <QMatrix4x4>

#include <memory>
#include <optional>

class QOpenGLFramebufferObject;

namespace cuelab {

class TablePass {
public:
    TablePass();
    ~TablePass();
    TablePass(const TablePass&) = delete;
    TablePass& operator=(const TablePass&) = delete;

    void create();
    void reset();
    void setTable(const Table& table);  // uploads the mesh at the next draw when the table changed
    void invalidateCache();             // the cue moved: the cached image holds the old one

    // Fills the bound framebuffer `target` (colour and depth) with the table and, when `cue` is given,
    // the stick placed by that model matrix. Returns whether something was drawn without the cache's
    // multisampling because the camera or the cue moved (one more still frame then draws it
    // antialiased).
    bool draw(const RenderFrame& frame, ShaderLibrary& shaders, const std::optional<QMatrix4x4>& cue, unsigned int target);

private:
    void upload();
    void drawTable(const RenderFrame& frame, ShaderLibrary& shaders);
    void drawCue(const RenderFrame& frame, ShaderLibrary& shaders, const QMatrix4x4& model);
    bool cacheValid(const RenderFrame& frame, int samples, const std::optional<QMatrix4x4>& cue) const;
    void buildCache(const RenderFrame& frame, ShaderLibrary& shaders, int samples, const std::optional<QMatrix4x4>& cue,
                    unsigned int target);

    static constexpr int kTableSamples = 4;
    Table table_;
    bool hasTable_ = false;
    bool dirty_ = true;
    GlVertexArray tableVao_, cueVao_;
    GlBuffer tableVbo_, cueVbo_;
    int tableCount_ = 0;
    int tableUncutCount_ = 0;  // vertices drawn without the pocket cut; the rest with it
    int cueCount_ = 0;
    int generation_ = 0;       // counts table uploads

    std::unique_ptr<QOpenGLFramebufferObject> cache_, multisampled_;
    QMatrix4x4 cacheViewProjection_;
    int cacheSamples_ = -1;
    int cacheGeneration_ = -1;
    std::optional<QMatrix4x4> cacheCue_;  // the cue drawn into the cache
    QMatrix4x4 lastViewProjection_;       // the camera of the previous frame, to tell a moving camera
    std::optional<QMatrix4x4> lastCue_;   // the cue of the previous frame, to tell a moving one
    bool hasLastFrame_ = false;
};

}  // namespace cuelab
