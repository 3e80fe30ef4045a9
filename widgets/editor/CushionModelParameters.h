#pragma once
// The parameters of the chosen ball-cushion model beyond restitution and friction (Mathavan's impulse
// steps, Stronge's frequency ratio), one spin box each, read from the model registry
// (core/physics/resolve/CushionModel.h): a new model's parameters appear here without a new line.
// Part of the Physics dock (PhysicsPanel adds it below the cushion friction); every change is an
// undoable edit of the document.

#include <QWidget>

#include <vector>

class QDoubleSpinBox;
class QFormLayout;

namespace cuelab {

class Document;
struct CushionModelParameter;

class CushionModelParameters : public QWidget {
    Q_OBJECT
public:
    explicit CushionModelParameters(Document* document, QWidget* parent = nullptr);

private:
    void rebuild();  // the spin boxes of the current model, with its values
    void commit(const CushionModelParameter& parameter, double value);

    Document* document_;
    QFormLayout* form_;
    int shownModel_ = -1;
    std::vector<QDoubleSpinBox*> boxes_;
    bool refreshing_ = false;
};

}  // namespace cuelab
