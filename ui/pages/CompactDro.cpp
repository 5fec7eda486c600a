#include "ui/pages/CompactDro.h"

#include "ui/i18n/PanelText.h"
#include "ui/widgets/MeasuredLabel.h"

#include <QEvent>
#include <QGridLayout>
#include <QLabel>

#include <cmath>

namespace m350::ui {

QString droText(double value) {
    if (std::abs(value) < 0.0005) {
        value = 0.0;
    }
    return QStringLiteral("%1").arg(value, 10, 'f', 3);
}

CompactDro::CompactDro(QWidget* parent) : QWidget(parent) {
    setObjectName("compactDro");
    auto* grid = new QGridLayout(this);
    grid->setContentsMargins(0, 0, 0, 0);
    grid->setHorizontalSpacing(12);
    grid->setVerticalSpacing(1);
    machineHeader_ = new MeasuredLabel(this);
    workHeader_ = new MeasuredLabel(this);
    for (QLabel* header : {machineHeader_, workHeader_}) {
        header->setObjectName("droHeader");
        header->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
    }
    grid->addWidget(machineHeader_, 0, 1);
    grid->addWidget(workHeader_, 0, 2);
    for (int axis = 0; axis < 5; ++axis) {
        const auto i = static_cast<std::size_t>(axis);
        names_[i] = new MeasuredLabel(PanelText::axis(axis), this);
        machine_[i] = new MeasuredLabel(this);
        work_[i] = new MeasuredLabel(this);
        units_[i] = new MeasuredLabel(this);
        units_[i]->setProperty("droUnit", true);
        for (QLabel* value : {machine_[i], work_[i]}) {
            value->setProperty("smallDro", true);
            value->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
        }
        grid->addWidget(names_[i], axis + 1, 0);
        grid->addWidget(machine_[i], axis + 1, 1);
        grid->addWidget(work_[i], axis + 1, 2);
        grid->addWidget(units_[i], axis + 1, 3);
    }
    grid->setColumnStretch(4, 1);
    retranslate();
}

void CompactDro::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) {
        retranslate();
    }
    QWidget::changeEvent(event);
}

void CompactDro::retranslate() {
    machineHeader_->setText(tr("Mach", "msg 34"));
    workHeader_->setText(tr("Abs", "msg 35"));
    rows_.fill(std::nullopt); // the units' words again
}

void CompactDro::render(const PanelSnapshot& snapshot) {
    const controller::PanelStatus& s = snapshot.status;
    for (int axis = 0; axis < 5; ++axis) {
        const auto i = static_cast<std::size_t>(axis);
        const bool shown = s.axisShown[i];
        const Row row{shown, s.axisName[i], s.axisRotary[i], s.machine(axis), s.work(axis)};
        if (rows_[i] == row) {
            continue;
        }
        rows_[i] = row;
        for (QLabel* label : {names_[i], machine_[i], work_[i], units_[i]}) {
            label->setVisible(shown);
        }
        names_[i]->setText(PanelText::axis(axis, s));
        units_[i]->setText(PanelText::axisUnit(axis, s));
        machine_[i]->setText(droText(s.machine(axis)));
        work_[i]->setText(droText(s.work(axis)));
    }
}

QString CompactDro::workText(int axis) const { return work_[static_cast<std::size_t>(axis)]->text().trimmed(); }
QString CompactDro::axisText(int axis) const { return names_[static_cast<std::size_t>(axis)]->text(); }
QString CompactDro::unitText(int axis) const { return units_[static_cast<std::size_t>(axis)]->text(); }
bool CompactDro::axisVisible(int axis) const { return !names_[static_cast<std::size_t>(axis)]->isHidden(); }

} // namespace m350::ui
