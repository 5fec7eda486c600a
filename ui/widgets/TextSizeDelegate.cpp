#include "ui/widgets/TextSizeDelegate.h"

#include <QAbstractItemView>
#include <QApplication>
#include <QEvent>
#include <QStyle>

namespace m350::ui {

TextSizeDelegate::TextSizeDelegate(QAbstractItemView* view) : QStyledItemDelegate(view) {
    view->installEventFilter(this);
    view->setItemDelegate(this);
}

QSize TextSizeDelegate::sizeHint(const QStyleOptionViewItem& option, const QModelIndex& index) const {
    if (const QVariant given = index.data(Qt::SizeHintRole); given.isValid()) {
        return qvariant_cast<QSize>(given);
    }
    QStyleOptionViewItem opt = option;
    initStyleOption(&opt, index);
    // what QStyledItemDelegate::sizeHint measures, from the same option
    auto measure = [&opt] {
        const QWidget* widget = opt.widget;
        QStyle* style = widget ? widget->style() : QApplication::style();
        return style->sizeFromContents(QStyle::CT_ItemViewItem, &opt, QSize(), widget);
    };
    if (opt.features & (QStyleOptionViewItem::HasDecoration | QStyleOptionViewItem::HasCheckIndicator)) {
        return measure();
    }
    const bool wraps = (opt.features & QStyleOptionViewItem::WrapText) && opt.rect.isValid();
    Key key{opt.text, opt.font, static_cast<int>(opt.features), static_cast<int>(opt.state),
            static_cast<int>(opt.displayAlignment), wraps ? opt.rect.width() : -1};
    if (auto found = sizes_.constFind(key); found != sizes_.constEnd()) {
        return *found;
    }
    if (sizes_.size() >= kMostRemembered) {
        sizes_.clear();
    }
    const QSize size = measure();
    sizes_.insert(std::move(key), size);
    return size;
}

// Installed on the view (and, by the view, on its editors: those events are the base class's).
bool TextSizeDelegate::eventFilter(QObject* watched, QEvent* event) {
    if (watched != parent()) {
        return QStyledItemDelegate::eventFilter(watched, event);
    }
    switch (event->type()) {
    case QEvent::StyleChange:
    case QEvent::FontChange:
    case QEvent::LanguageChange:
    case QEvent::LocaleChange: sizes_.clear(); break;
    default: break;
    }
    return false;
}

} // namespace m350::ui
