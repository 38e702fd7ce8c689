#include "ui/station/plan_editor_dialog.h"

#include <QCheckBox>
#include <QCoreApplication>
#include <QDialogButtonBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMenu>
#include <QMessageBox>
#include <QPushButton>
#include <QShortcut>
#include <QStandardPaths>
#include <QToolButton>
#include <QVBoxLayout>

#include <cmath>
#include <limits>

namespace imudesk::ui {

using station::ParamSpec;
using station::PlanStep;
using station::StepKind;
using station::TestPlan;

namespace {

// The catalogue's labels and tooltips are translated in TestPlan's context (test_plan.cpp
// marks them with QT_TRANSLATE_NOOP there).
QString planText(const char *text)
{
    return QCoreApplication::translate("imudesk::station::TestPlan", text);
}

// Decimals a value needs to be shown exactly (0..6).
int decimalsOf(double v)
{
    for (int d = 0; d < 6; ++d) {
        const double scaled = v * std::pow(10.0, d);
        if (std::abs(scaled - std::round(scaled)) < 1e-6)
            return d;
    }
    return 6;
}

QString number(double v)
{
    return QLocale().toString(v, 'g', 6);
}

// A spin box for a number of the catalogue: its range, unit and decimals.
QDoubleSpinBox *numberSpin(const ParamSpec &spec, int decimals, double value, QWidget *parent)
{
    auto *spin = new QDoubleSpinBox(parent);
    spin->setDecimals(decimals);
    spin->setRange(spec.min, spec.max);
    spin->setSingleStep(std::pow(10.0, -(decimals - 1)));
    if (*spec.unit)
        spin->setSuffix(QStringLiteral(" ") + QString::fromUtf8(spec.unit));
    spin->setCorrectionMode(QAbstractSpinBox::CorrectToNearestValue);
    spin->setValue(value);
    return spin;
}

} // namespace

PlanEditorDialog::PlanEditorDialog(TestPlan plan, QString path, QWidget *parent)
    : QDialog(parent), m_plan(std::move(plan)), m_path(std::move(path))
{
    setObjectName(QStringLiteral("planEditorDialog"));
    setModal(false);

    m_nameLabel = new QLabel(this);
    m_name = new QLineEdit(m_plan.name, this);
    m_name->setObjectName(QStringLiteral("planName"));
    m_nameLabel->setBuddy(m_name);
    m_conversionNote = new QLabel(this);
    m_conversionNote->setObjectName(QStringLiteral("conversionNote"));
    m_conversionNote->setWordWrap(true);
    m_conversionNote->setTextFormat(Qt::PlainText);
    connect(m_name, &QLineEdit::textEdited, this, [this](const QString &text) {
        m_plan.name = text;
        setModified();
    });

    // Left: the steps in order, each with its check box (enabled), and what moves them.
    m_stepsLabel = new QLabel(this);
    m_steps = new QListWidget(this);
    m_steps->setObjectName(QStringLiteral("planSteps"));
    m_stepsLabel->setBuddy(m_steps);
    connect(m_steps, &QListWidget::currentRowChanged, this, [this] {
        if (!m_filling) {
            buildForm();
            updateButtons();
        }
    });
    connect(m_steps, &QListWidget::itemChanged, this, &PlanEditorDialog::onItemChanged);
    m_up = new QPushButton(this);
    m_up->setObjectName(QStringLiteral("stepUp"));
    connect(m_up, &QPushButton::clicked, this, [this] { moveStep(-1); });
    m_down = new QPushButton(this);
    m_down->setObjectName(QStringLiteral("stepDown"));
    connect(m_down, &QPushButton::clicked, this, [this] { moveStep(1); });
    // Shortcut objects rather than the buttons' own: setText() (retranslation) resets those.
    auto *upKey = new QShortcut(QKeySequence(Qt::CTRL | Qt::Key_Up), this);
    connect(upKey, &QShortcut::activated, this, [this] { moveStep(-1); });
    auto *downKey = new QShortcut(QKeySequence(Qt::CTRL | Qt::Key_Down), this);
    connect(downKey, &QShortcut::activated, this, [this] { moveStep(1); });
    m_add = new QToolButton(this);
    m_add->setObjectName(QStringLiteral("stepAdd"));
    m_add->setPopupMode(QToolButton::InstantPopup);
    m_add->setToolButtonStyle(Qt::ToolButtonTextOnly);
    m_add->setMenu(new QMenu(m_add));
    m_remove = new QPushButton(this);
    m_remove->setObjectName(QStringLiteral("stepRemove"));
    connect(m_remove, &QPushButton::clicked, this, &PlanEditorDialog::removeStep);
    auto *removeKey = new QShortcut(QKeySequence::Delete, m_steps);
    removeKey->setContext(Qt::WidgetWithChildrenShortcut);
    connect(removeKey, &QShortcut::activated, this, &PlanEditorDialog::removeStep);
    auto *moveButtons = new QHBoxLayout;
    moveButtons->addWidget(m_up);
    moveButtons->addWidget(m_down);
    moveButtons->addWidget(m_add);
    moveButtons->addWidget(m_remove);
    auto *left = new QVBoxLayout;
    left->addWidget(m_stepsLabel);
    left->addWidget(m_steps, 1);
    left->addLayout(moveButtons);

    // Right: the selected step's description, its form and, under it, what keeps the plan
    // from running.
    m_stepTitle = new QLabel(this);
    m_stepTitle->setObjectName(QStringLiteral("stepTitle"));
    QFont bold = m_stepTitle->font();
    bold.setBold(true);
    m_stepTitle->setFont(bold);
    m_description = new QLabel(this);
    m_description->setObjectName(QStringLiteral("stepDescription"));
    m_description->setWordWrap(true);
    m_formHost = new QWidget(this);
    auto *hostLayout = new QVBoxLayout(m_formHost);
    hostLayout->setContentsMargins(0, 0, 0, 0);
    m_problems = new QLabel(this);
    m_problems->setObjectName(QStringLiteral("planProblems"));
    m_problems->setWordWrap(true);
    m_problems->setTextFormat(Qt::PlainText);
    m_problems->setTextInteractionFlags(Qt::TextSelectableByMouse);
    auto *right = new QVBoxLayout;
    right->addWidget(m_stepTitle);
    right->addWidget(m_description);
    right->addWidget(m_formHost);
    right->addWidget(m_problems);
    right->addStretch(1);

    auto *body = new QHBoxLayout;
    body->addLayout(left, 2);
    body->addLayout(right, 3);

    m_buttons = new QDialogButtonBox(this);
    m_save = m_buttons->addButton(QDialogButtonBox::Save);
    m_save->setObjectName(QStringLiteral("savePlan"));
    m_saveAs = m_buttons->addButton(QString(), QDialogButtonBox::ActionRole);
    m_saveAs->setObjectName(QStringLiteral("savePlanAs"));
    m_buttons->addButton(QDialogButtonBox::Close);
    m_save->setAutoDefault(false);
    m_saveAs->setAutoDefault(false);
    connect(m_save, &QPushButton::clicked, this, &PlanEditorDialog::save);
    connect(m_saveAs, &QPushButton::clicked, this, &PlanEditorDialog::saveAs);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto *saveKey = new QShortcut(QKeySequence::Save, this);
    connect(saveKey, &QShortcut::activated, this, &PlanEditorDialog::save);
    auto *saveAsKey = new QShortcut(QKeySequence::SaveAs, this);
    connect(saveAsKey, &QShortcut::activated, this, &PlanEditorDialog::saveAs);

    auto *nameRow = new QHBoxLayout;
    nameRow->addWidget(m_nameLabel);
    nameRow->addWidget(m_name, 1);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(nameRow);
    layout->addWidget(m_conversionNote);
    layout->addLayout(body, 1);
    layout->addWidget(m_buttons);

    retranslateUi(); // fills the list, the add menu and the form
    selectStep(m_plan.steps.empty() ? -1 : 0);
    resize(860, 560);
}

void PlanEditorDialog::retranslateUi()
{
    m_nameLabel->setText(tr("Plan &name:"));
    m_name->setToolTip(tr("Shown in the station window, the reports and the run folder's name"));
    m_stepsLabel->setText(tr("&Steps, in the order they run (unchecked: reported as skipped):"));
    m_up->setText(tr("Up"));
    m_up->setToolTip(tr("Move the step up (Ctrl+Up)"));
    m_down->setText(tr("Down"));
    m_down->setToolTip(tr("Move the step down (Ctrl+Down)"));
    m_add->setText(tr("Add"));
    m_add->setToolTip(tr("Add a step after the selected one"));
    m_add->menu()->clear();
    for (StepKind kind : TestPlan::allKinds()) {
        QAction *a = m_add->menu()->addAction(TestPlan::title(kind));
        a->setToolTip(TestPlan::description(kind));
        connect(a, &QAction::triggered, this, [this, kind] { addStep(kind); });
    }
    m_remove->setText(tr("Remove"));
    m_remove->setToolTip(tr("Remove the selected step (Delete)"));
    m_save->setText(tr("Save"));
    m_save->setToolTip(tr("Write the plan to its file (Ctrl+S)"));
    m_saveAs->setText(tr("Save as…"));
    m_saveAs->setToolTip(tr("Write the plan to another file; paths to its files follow it"));
    const int row = currentStep();
    fillSteps();
    selectStep(row);
    buildForm();
    updateProblems();
    updateTitle();
    updateButtons();
    updateConversionNote();
}

void PlanEditorDialog::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange && m_name)
        retranslateUi();
    QDialog::changeEvent(event);
}

void PlanEditorDialog::reject()
{
    if (m_modified) {
        const auto answer = QMessageBox::question(
            this, windowTitle(), tr("The plan has changes that are not saved."),
            QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
        if (answer == QMessageBox::Cancel || (answer == QMessageBox::Save && !save()))
            return;
    }
    QDialog::reject();
}

int PlanEditorDialog::currentStep() const
{
    const int row = m_steps->currentRow();
    return row >= 0 && row < int(m_plan.steps.size()) ? row : -1;
}

void PlanEditorDialog::selectStep(int index)
{
    if (index >= int(m_plan.steps.size()))
        index = int(m_plan.steps.size()) - 1;
    m_steps->setCurrentRow(index); // builds the form through currentRowChanged
}

QString PlanEditorDialog::stepItemText(int index) const
{
    return tr("%1. %2").arg(index + 1).arg(TestPlan::title(m_plan.steps[size_t(index)].kind));
}

void PlanEditorDialog::fillSteps()
{
    m_filling = true;
    const int row = m_steps->currentRow();
    m_steps->clear();
    for (int i = 0; i < int(m_plan.steps.size()); ++i) {
        auto *item = new QListWidgetItem(stepItemText(i), m_steps);
        item->setFlags(item->flags() | Qt::ItemIsUserCheckable);
        item->setCheckState(m_plan.steps[size_t(i)].enabled ? Qt::Checked : Qt::Unchecked);
        item->setToolTip(TestPlan::description(m_plan.steps[size_t(i)].kind));
    }
    if (row >= 0 && row < m_steps->count())
        m_steps->setCurrentRow(row);
    m_filling = false;
}

void PlanEditorDialog::onItemChanged(QListWidgetItem *item)
{
    if (m_filling)
        return;
    const int row = m_steps->row(item);
    if (row < 0 || row >= int(m_plan.steps.size()))
        return;
    const bool enabled = item->checkState() == Qt::Checked;
    if (m_plan.steps[size_t(row)].enabled == enabled)
        return;
    m_plan.steps[size_t(row)].enabled = enabled;
    if (row == currentStep())
        buildForm(); // its description says whether it runs
    setModified();
}

QWidget *PlanEditorDialog::field(const QString &key) const
{
    return m_form ? m_form->findChild<QWidget *>(QStringLiteral("param_") + key) : nullptr;
}

void PlanEditorDialog::buildForm()
{
    // A new form for the selected step; the spin boxes' typed values belong to the old one.
    delete m_form;
    m_form = new QWidget(m_formHost);
    m_formHost->layout()->addWidget(m_form);
    m_typedProblems.clear();
    auto *form = new QFormLayout(m_form);
    form->setContentsMargins(0, 0, 0, 0);
    form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    const int row = currentStep();
    if (row < 0) {
        m_stepTitle->setText(tr("No step selected"));
        m_description->setText(tr("Choose a step in the list to edit its limits, or add one."));
        updateProblems();
        return;
    }
    const PlanStep &s = m_plan.steps[size_t(row)];
    m_stepTitle->setText(tr("Step %1: %2").arg(row + 1).arg(TestPlan::title(s.kind)));
    m_description->setText(s.enabled ? TestPlan::description(s.kind)
                                     : tr("%1 This step is off: the reports list it as skipped.")
                                           .arg(TestPlan::description(s.kind)));
    const auto &specs = TestPlan::params(s.kind);
    if (specs.empty()) {
        auto *none = new QLabel(tr("This step has no parameters."), m_form);
        form->addRow(none);
    }
    for (const ParamSpec &spec : specs) {
        QWidget *editor = spec.text ? textField(row, spec) : numberField(row, spec);
        auto *label = new QLabel(tr("%1:").arg(planText(spec.label)), m_form);
        label->setToolTip(editor->toolTip());
        label->setBuddy(editor->focusProxy() ? editor->focusProxy() : editor);
        form->addRow(label, editor);
    }
    updateProblems();
}

QWidget *PlanEditorDialog::numberField(int step, const ParamSpec &spec)
{
    const QString key = QString::fromLatin1(spec.key);
    const PlanStep &s = m_plan.steps[size_t(step)];
    const double value = s.number(spec.key);
    const QString unit = QString::fromUtf8(spec.unit);
    // Enough decimals for the default, the least value, the value itself and its band, and one
    // more to tighten a limit; at most 4 (0.0001 °/s is below any module's noise).
    const int decimals = std::clamp(std::max({decimalsOf(spec.defaultValue), decimalsOf(spec.min), decimalsOf(value),
                                              decimalsOf(s.marginalOf(spec.key).value_or(0))})
                                        + 1,
                                    1, 4);
    auto *spin = numberSpin(spec, decimals, value, m_form);
    spin->setObjectName(QStringLiteral("param_") + key);
    const QString withUnit = unit.isEmpty() ? QString() : QStringLiteral(" ") + unit;
    spin->setToolTip(tr("%1\nFrom %2%4 to %3%4; default %5%4.")
                         .arg(planText(spec.tooltip), number(spec.min), number(spec.max), withUnit,
                              number(spec.defaultValue)));
    connect(spin, &QDoubleSpinBox::valueChanged, this, [this, step, key](double v) {
        if (step >= int(m_plan.steps.size()))
            return;
        m_plan.steps[size_t(step)].params[key] = v;
        setModified();
    });
    watchTyped(spin, step, spec, key, false);
    return spec.limit ? limitField(step, spec, spin) : spin;
}

QWidget *PlanEditorDialog::limitField(int step, const ParamSpec &spec, QDoubleSpinBox *limit)
{
    const QString key = QString::fromLatin1(spec.key);
    const auto band = m_plan.steps[size_t(step)].marginalOf(spec.key);
    auto *row = new QWidget(m_form);
    row->setToolTip(limit->toolTip());
    auto *layout = new QHBoxLayout(row);
    layout->setContentsMargins(0, 0, 0, 0);
    limit->setParent(row);
    layout->addWidget(limit, 1);
    auto *check = new QCheckBox(tr("Marginal band"), row);
    check->setObjectName(QStringLiteral("marginalBand_") + key);
    check->setToolTip(tr("Mark values close to the limit: they still pass, and the results say they were marginal"));
    check->setChecked(band.has_value());
    layout->addWidget(check);
    // Without a band yet, one at four fifths of the limit is offered: checking the box gives a
    // band that is valid at once.
    auto *bandSpin = numberSpin(spec, limit->decimals(), band.value_or(limit->value() * 0.8), row);
    bandSpin->setObjectName(QStringLiteral("marginal_") + key);
    const QString unit = *spec.unit ? QStringLiteral(" ") + QString::fromUtf8(spec.unit) : QString();
    bandSpin->setToolTip(tr("Values above this, up to the limit, pass marked marginal.\nFrom %1%3 to %2%3, below "
                            "the limit.")
                             .arg(number(spec.min), number(spec.max), unit));
    bandSpin->setEnabled(check->isChecked());
    layout->addWidget(bandSpin, 1);
    row->setFocusProxy(limit);
    connect(check, &QCheckBox::toggled, this, [this, step, key, bandSpin](bool on) {
        if (step >= int(m_plan.steps.size()))
            return;
        bandSpin->setEnabled(on);
        if (on) {
            m_plan.steps[size_t(step)].marginal[key] = bandSpin->value();
        } else {
            m_plan.steps[size_t(step)].marginal.remove(key);
            m_typedProblems.remove(QStringLiteral("marginal_") + key);
        }
        setModified();
    });
    connect(bandSpin, &QDoubleSpinBox::valueChanged, this, [this, step, key, check](double v) {
        if (step >= int(m_plan.steps.size()) || !check->isChecked())
            return;
        m_plan.steps[size_t(step)].marginal[key] = v;
        setModified(); // a band at or above the limit is listed by the plan's problems
    });
    watchTyped(bandSpin, step, spec, QStringLiteral("marginal_") + key, true);
    return row;
}

void PlanEditorDialog::watchTyped(QDoubleSpinBox *spin, int step, const ParamSpec &spec, const QString &problemKey,
                                  bool band)
{
    // A value being typed outside the range is not taken by the spin box (it keeps the last
    // one, then corrects to the nearest limit): say so while it is typed.
    auto *edit = spin->findChild<QLineEdit *>();
    if (!edit)
        return;
    const QString key = QString::fromLatin1(spec.key);
    connect(edit, &QLineEdit::textChanged, this, [this, spin, step, key, problemKey, spec, band] {
        if (step >= int(m_plan.steps.size()))
            return;
        const StepKind kind = m_plan.steps[size_t(step)].kind;
        const QString typed = spin->cleanText();
        bool ok = false;
        const double v = spin->locale().toDouble(typed, &ok);
        QString why;
        if (!ok)
            why = tr("\"%1\" needs a number from %2 to %3").arg(key, number(spec.min), number(spec.max));
        else if (band) // the range only: a band the box takes that is not below the limit is the plan's problem
            why = TestPlan::checkMarginal(kind, key, QVariant(v), QVariant(std::numeric_limits<double>::infinity()));
        else
            why = TestPlan::checkValue(kind, key, QVariant(v));
        if (why.isEmpty())
            m_typedProblems.remove(problemKey);
        else
            m_typedProblems.insert(problemKey, tr("step %1 (%2): %3").arg(step + 1).arg(TestPlan::key(kind), why));
        updateProblems();
    });
}

QWidget *PlanEditorDialog::textField(int step, const ParamSpec &spec)
{
    const QString key = QString::fromLatin1(spec.key);
    const StepKind kind = m_plan.steps[size_t(step)].kind;
    auto *edit = new QLineEdit(m_plan.steps[size_t(step)].text(spec.key), m_form);
    edit->setObjectName(QStringLiteral("param_") + key);
    const QString def = QString::fromUtf8(spec.defaultText);
    edit->setToolTip(def.isEmpty() ? planText(spec.tooltip)
                                   : tr("%1\nDefault: %2").arg(planText(spec.tooltip), def));
    edit->setClearButtonEnabled(true);
    connect(edit, &QLineEdit::textEdited, this, [this, step, key](const QString &text) {
        if (step >= int(m_plan.steps.size()))
            return;
        m_plan.steps[size_t(step)].params[key] = text;
        setModified();
    });
    if (!isPathParam(kind, key))
        return edit;
    // A file: the line and Browse…, in one row of the form.
    auto *row = new QWidget(m_form);
    row->setToolTip(edit->toolTip());
    auto *layout = new QHBoxLayout(row);
    layout->setContentsMargins(0, 0, 0, 0);
    edit->setParent(row);
    layout->addWidget(edit, 1);
    auto *browseButton = new QPushButton(tr("Browse…"), row);
    browseButton->setObjectName(QStringLiteral("browse_") + key);
    browseButton->setToolTip(tr("Choose the file; inside the plan's folder it is kept relative to it"));
    layout->addWidget(browseButton);
    row->setFocusProxy(edit);
    connect(browseButton, &QPushButton::clicked, this, [this, step, key, edit] { browse(step, key, edit); });
    return row;
}

bool PlanEditorDialog::isPathParam(StepKind kind, const QString &key)
{
    return (kind == StepKind::Firmware && key == QLatin1String("image"))
        || (kind == StepKind::Profile && key == QLatin1String("profile"));
}

QString PlanEditorDialog::relativeIfInside(const QString &absolute, const QString &dir)
{
    if (dir.isEmpty())
        return absolute;
    const QString relative = QDir(dir).relativeFilePath(absolute);
    if (relative.startsWith(QLatin1String("..")) || QFileInfo(relative).isAbsolute())
        return absolute;
    return relative;
}

void PlanEditorDialog::browse(int step, const QString &key, QLineEdit *edit)
{
    if (step >= int(m_plan.steps.size()))
        return;
    const StepKind kind = m_plan.steps[size_t(step)].kind;
    QString start = m_plan.resolve(edit->text());
    if (start.isEmpty() || !QFileInfo::exists(start))
        start = m_plan.baseDir.isEmpty() ? QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation)
                                         : m_plan.baseDir;
    const QString filter = kind == StepKind::Firmware
        ? tr("Firmware images (*.hex *.ihex *.bin);;All files (*)")
        : tr("Configuration profiles (*.json);;All files (*)");
    const QString chosen = QFileDialog::getOpenFileName(this, tr("Choose a file for \"%1\"").arg(TestPlan::title(kind)),
                                                        start, filter);
    if (chosen.isEmpty())
        return;
    const QString value = relativeIfInside(QFileInfo(chosen).absoluteFilePath(), m_plan.baseDir);
    edit->setText(value);
    m_plan.steps[size_t(step)].params[key] = value;
    setModified();
}

void PlanEditorDialog::addStep(StepKind kind)
{
    const int at = currentStep() < 0 ? int(m_plan.steps.size()) : currentStep() + 1;
    m_plan.steps.insert(m_plan.steps.begin() + at, TestPlan::defaultStep(kind));
    fillSteps();
    selectStep(at);
    setModified();
}

void PlanEditorDialog::removeStep()
{
    const int row = currentStep();
    if (row < 0)
        return;
    m_plan.steps.erase(m_plan.steps.begin() + row);
    fillSteps();
    selectStep(std::min(row, int(m_plan.steps.size()) - 1));
    buildForm();
    setModified();
}

void PlanEditorDialog::moveStep(int delta)
{
    const int row = currentStep();
    const int to = row + delta;
    if (row < 0 || to < 0 || to >= int(m_plan.steps.size()))
        return;
    std::swap(m_plan.steps[size_t(row)], m_plan.steps[size_t(to)]);
    fillSteps();
    selectStep(to);
    setModified();
}

void PlanEditorDialog::setModified()
{
    m_modified = true;
    updateProblems();
    updateTitle();
    updateButtons();
}

QStringList PlanEditorDialog::problems() const
{
    QStringList out = m_plan.problems();
    for (const QString &p : m_typedProblems)
        out << p;
    return out;
}

void PlanEditorDialog::updateProblems()
{
    const QStringList list = problems();
    if (list.isEmpty()) {
        m_problems->setText(tr("The plan can run."));
        m_problems->setStyleSheet(QStringLiteral("color: #2e7d32;"));
        return;
    }
    m_problems->setText(tr("The plan cannot run yet:") + QStringLiteral("\n• ") + list.join(QStringLiteral("\n• ")));
    m_problems->setStyleSheet(QStringLiteral("color: #c62828;"));
}

void PlanEditorDialog::updateTitle()
{
    const QString name = m_plan.name.isEmpty() ? tr("(no name)") : m_plan.name;
    const QString file = m_path.isEmpty() ? tr("not saved") : QDir::toNativeSeparators(m_path);
    setWindowTitle(tr("Test plan – %1 (%2)%3").arg(name, file, m_modified ? QStringLiteral(" *") : QString()));
}

void PlanEditorDialog::updateConversionNote()
{
    const QString note = m_plan.conversionNote();
    m_conversionNote->setText(note);
    m_conversionNote->setVisible(!note.isEmpty());
}

void PlanEditorDialog::updateButtons()
{
    const int row = currentStep();
    m_up->setEnabled(row > 0);
    m_down->setEnabled(row >= 0 && row + 1 < int(m_plan.steps.size()));
    m_remove->setEnabled(row >= 0);
}

bool PlanEditorDialog::save()
{
    return m_path.isEmpty() ? saveAs() : saveTo(m_path);
}

bool PlanEditorDialog::saveAs()
{
    QString start = m_path;
    if (start.isEmpty()) {
        const QString folder = m_plan.baseDir.isEmpty()
            ? QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation)
            : m_plan.baseDir;
        const QString name = m_plan.name.trimmed().isEmpty() ? QStringLiteral("station-plan") : m_plan.name.trimmed();
        start = QDir(folder).filePath(name + QStringLiteral(".json"));
    }
    QString path = QFileDialog::getSaveFileName(this, tr("Save test plan"), start, tr("Station plans (*.json)"));
    if (path.isEmpty())
        return false;
    if (QFileInfo(path).suffix().isEmpty())
        path += QStringLiteral(".json");
    return saveTo(path);
}

bool PlanEditorDialog::saveTo(const QString &path)
{
    TestPlan out = m_plan;
    const QString dir = QFileInfo(path).absolutePath();
    // The files the plan names stay the same files: a relative path is re-based on the new
    // folder (relative again when the file is inside it, else absolute).
    if (!m_plan.baseDir.isEmpty() && QDir(dir) != QDir(m_plan.baseDir)) {
        for (PlanStep &s : out.steps)
            for (auto it = s.params.begin(); it != s.params.end(); ++it) {
                const QString value = it.value().toString();
                if (!isPathParam(s.kind, it.key()) || value.isEmpty() || QFileInfo(value).isAbsolute())
                    continue;
                it.value() = relativeIfInside(QFileInfo(m_plan.resolve(value)).absoluteFilePath(), dir);
            }
    }
    out.baseDir = dir;
    QString error;
    if (!out.save(path, &error)) {
        showError(error);
        return false;
    }
    m_plan = std::move(out);
    m_plan.loadedVersion = TestPlan::kVersion; // written in the current format now
    m_path = QFileInfo(path).absoluteFilePath();
    m_modified = false;
    updateConversionNote();
    buildForm(); // re-based paths, and "not found" problems judged from the new folder
    updateTitle();
    Q_EMIT saved(m_plan, m_path);
    return true;
}

void PlanEditorDialog::showError(const QString &message)
{
    // Never block: a non-modal box.
    auto *box = new QMessageBox(QMessageBox::Warning, tr("Test plan"), message, QMessageBox::Ok, this);
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->setWindowModality(Qt::NonModal);
    box->show();
}

} // namespace imudesk::ui
