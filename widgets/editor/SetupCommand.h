#pragma once
// One undoable edit of a setup: the whole setup before and after. A setup is a few hundred bytes, so
// a snapshot is cheaper and far harder to get wrong than per-field inverse operations.

#include "Setup.h"

#include <QUndoCommand>

namespace cuelab {

class Document;

// Edits that merge while the user keeps changing the same thing (a drag, a slider, a spin box's
// arrows) carry a kind and a target; two consecutive commands merge when both match and the
// document has not closed the merge session in between (Document::endMerge()).
enum class MergeKind : int {
    None = -1,
    MoveBall = 1,   // target: ball index
    BallField,      // target: ball index * 16 + field
    Physics,        // target: field
    Shot,           // target: field
    Simulation,     // target: field
};

struct MergeKey {
    MergeKind kind = MergeKind::None;
    int target = 0;
};

class SetupCommand : public QUndoCommand {
public:
    SetupCommand(Document* document, const QString& text, Setup before, Setup after, MergeKey merge,
                 int mergeSession, QUndoCommand* parent = nullptr);

    void undo() override;
    void redo() override;
    int id() const override;
    bool mergeWith(const QUndoCommand* other) override;

private:
    Document* document_;
    Setup before_;
    Setup after_;
    MergeKey merge_;
    int mergeSession_;
};

}  // namespace cuelab
