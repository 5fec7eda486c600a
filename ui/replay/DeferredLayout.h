#pragma once

#include <QObject>
#include <QPointer>
#include <QSet>

#include <vector>

namespace m350::ui {

// While it lives, the widgets' layout requests wait instead of running after every action: a
// headless replay lays the panel out only where something reads its geometry (a list's scroll
// position, a prompt's width) and at the end. Each widget's request is kept once, in the order
// they came; catchUp() runs them (and what they ask in turn) as the event loop would have.
class DeferredLayout : public QObject {
    Q_OBJECT
public:
    explicit DeferredLayout(QObject* parent = nullptr);
    ~DeferredLayout() override; // catches up and lets requests through again

    void catchUp();
    bool pending() const { return !held_.empty(); }

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    std::vector<QPointer<QObject>> held_;
    QSet<QObject*> heldSet_;
    bool passing_ = false;
};

} // namespace m350::ui
