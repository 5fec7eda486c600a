#pragma once

#include "ui/pages/Page.h"
#include "ui/pages/PageId.h"

namespace m350::ui {

class MachineView;
struct MachineViewContent;

// 图形显示 (the Monitor's F1): the machine view of the loaded program and the machine, live.
// F1 top view, F2 front view (both side by side on a wide window), F3 fit the path (again: the
// whole machine), F4 / F5 zoom in / out;
// the arrow keys pan; a click on the path opens its line in the editor. Esc goes back.
class GraphicsPage : public Page {
    Q_OBJECT
public:
    explicit GraphicsPage(PanelContext& context, QWidget* parent = nullptr);
    QString id() const override { return PageId::graphics; }
    QString title() const override;
    QVector<Softkey> softkeys() const override;
    void softkey(int number) override;
    bool key(const QString& name) override;
    void render(const PanelSnapshot& snapshot) override;
    bool rendersEverySnapshot() const override { return true; }
    bool readsLayout() const override { return true; } // the view fits a new path to its size
    bool drawsMachine() const override { return true; }
    QJsonObject state() const override;

    MachineView* view() const { return view_; }
    // What the machine view shows of `snapshot`: the loaded program's path, the run's progress on
    // it, the machine, the spindle and the alarm.
    static MachineViewContent contentOf(const PanelSnapshot& snapshot);

private:
    QString sourcePath(const QString& name) const;
    MachineView* view_;
};

} // namespace m350::ui
