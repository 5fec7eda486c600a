#include "ui/panel/SoftkeyBar.h"

#include "ui/panel/SoftkeyButton.h"

#include <QGridLayout>

namespace m350::ui {

SoftkeyBar::SoftkeyBar(QWidget* parent) : QWidget(parent) {
    setObjectName("softkeyBar");
    auto* grid = new QGridLayout(this);
    grid->setContentsMargins(2, 2, 2, 2);
    grid->setSpacing(3);
    for (int number = 1; number <= 12; ++number) {
        auto* button = new SoftkeyButton(this);
        button->setObjectName(QStringLiteral("softkey%1").arg(number));
        button->setFocusPolicy(Qt::NoFocus);
        button->setMinimumHeight(34);
        button->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
        connect(button, &QPushButton::clicked, this, [this, number] { emit pressed(number); });
        grid->addWidget(button, (number - 1) / 6, (number - 1) % 6);
        buttons_.push_back(button);
    }
}

void SoftkeyBar::show(const QVector<Page::Softkey>& keys) {
    const bool twoRows = keys.size() > 6;
    for (int i = 0; i < 12; ++i) {
        QPushButton* button = buttons_[i];
        if (i >= 6 && !twoRows) {
            button->hide();
            continue;
        }
        button->show();
        const Page::Softkey key = i < keys.size() ? keys[i] : Page::Softkey{{}, false, {}};
        // The second row is SHIFT with F1-F6 (the M350's SHIFT key, code 1025), marked ⇧F1-⇧F6.
        QString f = (i < 6 ? QStringLiteral("F%1") : QStringLiteral("\u21e7F%1")).arg(i % 6 + 1);
        button->setText(key.text.isEmpty() ? QString() : f + QLatin1Char(' ') + key.text);
        button->setEnabled(key.enabled && !key.text.isEmpty());
        button->setToolTip(key.tooltip);
    }
}

QString SoftkeyBar::label(int number) const { return buttons_[number - 1]->text(); }
bool SoftkeyBar::enabled(int number) const { return buttons_[number - 1]->isEnabled(); }

} // namespace m350::ui
