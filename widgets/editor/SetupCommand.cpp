#include "SetupCommand.h"

#include "Document.h"

namespace cuelab {

SetupCommand::SetupCommand(Document* document, const QString& text, Setup before, Setup after,
                           MergeKey merge, int mergeSession, QUndoCommand* parent)
    : QUndoCommand(text, parent),
      document_(document),
      before_(std::move(before)),
      after_(std::move(after)),
      merge_(merge),
      mergeSession_(mergeSession)
{
}

void SetupCommand::undo() { document_->applySetup(before_); }

void SetupCommand::redo() { document_->applySetup(after_); }

int SetupCommand::id() const { return static_cast<int>(merge_.kind); }

bool SetupCommand::mergeWith(const QUndoCommand* other)
{
    // QUndoStack only calls this for commands with the same id(), i.e. the same MergeKind.
    const auto* next = static_cast<const SetupCommand*>(other);
    if (next->merge_.target != merge_.target || next->mergeSession_ != mergeSession_) return false;
    after_ = next->after_;
    return true;
}

}  // namespace cuelab
