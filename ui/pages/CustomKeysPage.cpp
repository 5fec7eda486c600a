#include "ui/pages/CustomKeysPage.h"

#include "ui/pages/PanelContext.h"

#include "core/config/HookFiles.h"
#include "ui/widgets/WrappedLabel.h"

#include <QDir>
#include <QFileInfo>
#include <QGridLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

#include <algorithm>

namespace m350::ui {

namespace {

constexpr int kColumns = 7;
constexpr int kFirstMCode = 250; // FUNC K01 = M250 .. K14 = M263

QString hookFileName() {
    const std::string_view name = config::hookFile(config::Hook::ExtButton).fileName;
    return QString::fromUtf8(name.data(), static_cast<qsizetype>(name.size()));
}

} // namespace

CustomKeysPage::CustomKeysPage(PanelContext& context, QWidget* parent) : Page(context, parent) {
    setObjectName("customKeysPage");
    auto* column = new QVBoxLayout(this);
    column->setContentsMargins(8, 8, 8, 8);
    auto* grid = new QGridLayout;
    grid->setSpacing(8);
    for (int key = 1; key <= kKeys; ++key) {
        auto* button = new QPushButton(this);
        button->setObjectName(QStringLiteral("funcK%1").arg(key, 2, 10, QLatin1Char('0')));
        button->setCheckable(true);
        button->setFocusPolicy(Qt::NoFocus);
        button->setMinimumHeight(64);
        connect(button, &QPushButton::clicked, this, [this, key] {
            select(key);
            press();
        });
        keys_[static_cast<std::size_t>(key - 1)] = button;
        grid->addWidget(button, (key - 1) / kColumns, (key - 1) % kColumns);
    }
    column->addLayout(grid);
    runs_ = new WrappedLabel(this);
    runs_->setObjectName("customKeysRuns");
    column->addWidget(runs_);
    column->addStretch(1);
    retranslate();
    select(1);
}

QString CustomKeysPage::title() const { return tr("Manual", "msg 318"); }

void CustomKeysPage::retranslate() {
    // the firmware's names, msg 150-163 (扩展按键01-14)
    static const struct { const char* source; const char* comment; } names[kKeys] = {
        QT_TRANSLATE_NOOP3("m350::ui::CustomKeysPage", "FUNC K01", "msg 150"),
        QT_TRANSLATE_NOOP3("m350::ui::CustomKeysPage", "FUNC K02", "msg 151"),
        QT_TRANSLATE_NOOP3("m350::ui::CustomKeysPage", "FUNC K03", "msg 152"),
        QT_TRANSLATE_NOOP3("m350::ui::CustomKeysPage", "FUNC K04", "msg 153"),
        QT_TRANSLATE_NOOP3("m350::ui::CustomKeysPage", "FUNC K05", "msg 154"),
        QT_TRANSLATE_NOOP3("m350::ui::CustomKeysPage", "FUNC K06", "msg 155"),
        QT_TRANSLATE_NOOP3("m350::ui::CustomKeysPage", "FUNC K07", "msg 156"),
        QT_TRANSLATE_NOOP3("m350::ui::CustomKeysPage", "FUNC K08", "msg 157"),
        QT_TRANSLATE_NOOP3("m350::ui::CustomKeysPage", "FUNC K09", "msg 158"),
        QT_TRANSLATE_NOOP3("m350::ui::CustomKeysPage", "FUNC K10", "msg 159"),
        QT_TRANSLATE_NOOP3("m350::ui::CustomKeysPage", "FUNC K11", "msg 160"),
        QT_TRANSLATE_NOOP3("m350::ui::CustomKeysPage", "FUNC K12", "msg 161"),
        QT_TRANSLATE_NOOP3("m350::ui::CustomKeysPage", "FUNC K13", "msg 162"),
        QT_TRANSLATE_NOOP3("m350::ui::CustomKeysPage", "FUNC K14", "msg 163"),
    };
    for (int key = 1; key <= kKeys; ++key) {
        keys_[static_cast<std::size_t>(key - 1)]->setText(
            tr(names[key - 1].source, names[key - 1].comment) + QStringLiteral("\nM%1").arg(kFirstMCode + key - 1));
    }
    updateRuns();
}

void CustomKeysPage::updateRuns() {
    runs_->setText(folderHasHook()
                       ? tr("%1 runs M#1996 (#1996 = M250-M263 for K01-K14). UP/DOWN/LEFT/RIGHT: key, ENTER: press.")
                             .arg(hookFileName())
                       : tr("No %1 in the machine folder: a key runs its M code (M250-M263) as MDI. "
                            "UP/DOWN/LEFT/RIGHT: key, ENTER: press.")
                             .arg(hookFileName()));
}

QVector<Page::Softkey> CustomKeysPage::softkeys() const {
    return {{tr("Manual", "msg 480"), true, tr("Presses the selected FUNC key")},
            {},
            {tr("CAM", "msg 482"), false, tr("The CAM wizard pages (CAM.nc) are not simulated")},
            {},
            {},
            {}};
}

void CustomKeysPage::softkey(int number) {
    if (number == 1) {
        press();
    }
}

bool CustomKeysPage::key(const QString& name) {
    if (name == QLatin1String("ESC")) {
        emit navigate(PageId::monitor);
    } else if (name == QLatin1String("ENTER")) {
        press();
    } else if (name == QLatin1String("LEFT") || name == QLatin1String("RIGHT")) {
        select(selected_ + (name == QLatin1String("LEFT") ? -1 : 1));
    } else if (name == QLatin1String("UP") || name == QLatin1String("DOWN")) {
        select(selected_ + (name == QLatin1String("UP") ? -kColumns : kColumns));
    } else {
        return false;
    }
    return true;
}

void CustomKeysPage::select(int key) {
    selected_ = std::clamp(key, 1, kKeys);
    for (int k = 1; k <= kKeys; ++k) {
        keys_[static_cast<std::size_t>(k - 1)]->setChecked(k == selected_);
    }
}

void CustomKeysPage::press() { context().session().functionKey(selected_); }

bool CustomKeysPage::folderHasHook() const {
    return QFileInfo::exists(QDir(context().machineFolder()).filePath(hookFileName()));
}

// the folder may get its ext_button.nc while the panel runs (the Program page's system disk); the
// panel renders the page it is on alone
void CustomKeysPage::render(const PanelSnapshot& snapshot) {
    (void)snapshot;
    updateRuns();
}

QJsonObject CustomKeysPage::state() const {
    return {{"selected_key", selected_}, {"runs", runs_->text()}};
}

} // namespace m350::ui
