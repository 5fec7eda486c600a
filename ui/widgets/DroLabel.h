#pragma once

#include <QLabel>

namespace m350::ui {

// A coordinate of the big DRO: its font is the largest that shows the widest coordinate
// ("-99999.999") in the width and height the layout gives it, so no screen size cuts a digit or
// the sign off (800x480) and a larger window shows larger digits. Its minimum size is the 7 pt
// text's, not its font's: the font follows the size the layout gives it.
class DroLabel : public QLabel {
    Q_OBJECT
public:
    explicit DroLabel(QWidget* parent = nullptr);
    QSize minimumSizeHint() const override;
    QSize sizeHint() const override;
    // The text the font must fit: the widest a coordinate gets.
    static QString widestText();

protected:
    void resizeEvent(QResizeEvent* event) override;

private:
    void fitFont();
};

} // namespace m350::ui
