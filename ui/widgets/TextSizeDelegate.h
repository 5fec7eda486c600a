#pragma once

#include <QFont>
#include <QHash>
#include <QSize>
#include <QString>
#include <QStyledItemDelegate>

namespace m350::ui {

// Item delegate of the panel's tables and lists that remembers what a cell's text measured. Qt
// measures a fitted column's every row each time the table is shown, hidden or laid out (the
// System Log's 500 rows at every page switch): the size of the same text in the same font is
// what it was, so it is measured once. Cells with an icon, a check box or wrapped text in a given
// width are measured as Qt always does. The view's style or font changing forgets everything.
class TextSizeDelegate : public QStyledItemDelegate {
    Q_OBJECT
public:
    explicit TextSizeDelegate(QAbstractItemView* view);

    QSize sizeHint(const QStyleOptionViewItem& option, const QModelIndex& index) const override;

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    struct Key {
        QString text;
        QFont font;
        int features = 0;
        int state = 0;
        int alignment = 0;
        int wrapWidth = -1;
        bool operator==(const Key&) const = default;
    };
    friend size_t qHash(const Key& key, size_t seed = 0) noexcept {
        return qHashMulti(seed, key.text, key.font, key.features, key.state, key.alignment, key.wrapWidth);
    }
    static constexpr qsizetype kMostRemembered = 8192; // then forgotten and measured again
    mutable QHash<Key, QSize> sizes_;
};

} // namespace m350::ui
