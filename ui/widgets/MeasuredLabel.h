#pragma once

#include <QLabel>

#include <list>
#include <utility>
#include <vector>

namespace m350::ui {

// A label whose text changes as the panel runs (a page's caption, the selected row's details, the
// status line). Qt measures a label again after every change of its text, laying the text out
// once or more per question, and a layout asks its size, its least size and its height for a
// width at each pass: on the Param page each cursor key spent half its time there. The answers
// are kept for the last texts shown (a cursor moving up and down a list comes back to them) until
// the font or the style change; what the answers depend on besides the text (format, alignment,
// wrapping, indent, margin, the widest size allowed) is part of what they are kept by.
class MeasuredLabel : public QLabel {
    Q_OBJECT
public:
    explicit MeasuredLabel(QWidget* parent = nullptr);
    MeasuredLabel(const QString& text, QWidget* parent);
    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;
    int heightForWidth(int width) const override;

protected:
    void changeEvent(QEvent* event) override;

private:
    struct Shape {
        QString text;
        int format = 0;
        int alignment = 0;
        bool wrapped = false;
        int indent = 0;
        int margin = 0;
        int widest = 0;
        bool operator==(const Shape& other) const = default;
    };
    struct Measures {
        Shape shape;
        QSize size;
        QSize least;
        std::vector<std::pair<int, int>> heights; // (width, height)
    };
    Shape shape() const;
    Measures& measures() const; // of the current text, measured at first ask

    mutable std::list<Measures> kept_; // the latest first
};

} // namespace m350::ui
