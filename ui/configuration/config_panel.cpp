#include "configuration/config_panel.h"

#include "device/device_session.h"
#include "itemmodels/settings_table_model.h"
#include "configuration/mounting_picker.h"
#include "settings/bandwidth_calculator.h"
#include "settings/setting_catalog.h"
#include "configuration/setting_value_delegate.h"

#include <QApplication>
#include <QClipboard>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QGroupBox>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QMenu>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSettings>
#include <QSplitter>
#include <QTableView>
#include <QVBoxLayout>

namespace imudesk::ui {

using settings::ConfigurationController;
using settings::SettingCatalog;

namespace {
constexpr int kMaxLogBlocks = 2000;
}

ConfigPanel::ConfigPanel(device::DeviceSession &session, QWidget *parent)
    : QWidget(parent), m_session(session), m_controller(std::make_unique<ConfigurationController>(session)),
      m_model(new models::SettingsTableModel(this))
{
    m_confirm = [this](const QString &title, const QString &text) {
        return QMessageBox::warning(this, title, text, QMessageBox::Yes | QMessageBox::Cancel, QMessageBox::Cancel)
            == QMessageBox::Yes;
    };
    auto *layout = new QVBoxLayout(this);
    m_identity = new QLabel(this);
    layout->addWidget(m_identity);

    auto *bar = new QHBoxLayout;
    for (const char *key : {"read", "apply", "save", "reboot", "freset", "mounting"}) {
        auto *b = new QPushButton(this);
        m_buttons[QLatin1String(key)] = b;
        bar->addWidget(b);
    }
    bar->addStretch(1);
    layout->addLayout(bar);

    auto *split = new QSplitter(Qt::Vertical, this);
    m_table = new QTableView(split);
    m_table->setModel(m_model);
    auto *delegate = new SettingValueDelegate(m_table);
    m_table->setItemDelegateForColumn(models::SettingsTableModel::NewColumn, delegate);
    m_table->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::SelectedClicked
                             | QAbstractItemView::EditKeyPressed);
    m_table->verticalHeader()->hide();
    // Rows of one line of text (the style's default is 30 px): more settings in view on a laptop.
    m_table->verticalHeader()->setMinimumSectionSize(m_table->fontMetrics().height() + 8);
    m_table->verticalHeader()->setDefaultSectionSize(m_table->fontMetrics().height() + 8);
    m_table->setWordWrap(false);
    // What a setting is, what it holds and what it will be: always in view, never behind a
    // horizontal scroll bar. The key, when it takes effect and what reads it back are in every
    // cell's tooltip, and the header's context menu shows them as columns (remembered).
    QHeaderView *header = m_table->horizontalHeader();
    header->setSectionResizeMode(QHeaderView::ResizeToContents);
    header->setSectionResizeMode(models::SettingsTableModel::NameColumn, QHeaderView::Stretch);
    header->setContextMenuPolicy(Qt::CustomContextMenu);
    m_table->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    connect(header, &QWidget::customContextMenuRequested, this, [this](const QPoint &pos) {
        QMenu menu(this);
        for (int c : kOptionalColumns) {
            QAction *a = menu.addAction(m_model->headerData(c, Qt::Horizontal).toString());
            a->setCheckable(true);
            a->setChecked(!m_table->isColumnHidden(c));
            connect(a, &QAction::toggled, this, [this, c](bool on) { setColumnShown(c, on); });
        }
        menu.exec(m_table->horizontalHeader()->mapToGlobal(pos));
    });
    {
        const QStringList shown = QSettings().value(QLatin1String(kShownColumnsKey)).toStringList();
        for (int c : kOptionalColumns)
            m_table->setColumnHidden(c, !shown.contains(QString::number(c)));
    }
    connect(delegate, &SettingValueDelegate::valueRefused, this, [this](const QString &why) { log(why, true); });

    auto *lower = new QWidget(split);
    auto *lowerLayout = new QVBoxLayout(lower);
    lowerLayout->setContentsMargins(0, 0, 0, 0);
    m_link = new QLabel(lower);
    m_link->setWordWrap(true);
    lowerLayout->addWidget(m_link);
    auto *pendingRow = new QHBoxLayout;
    m_pending = new QPlainTextEdit(lower);
    m_pending->setReadOnly(true);
    m_pending->setMaximumBlockCount(kMaxLogBlocks);
    const int line = m_pending->fontMetrics().lineSpacing();
    m_pending->setMaximumHeight(4 * line + 12);
    pendingRow->addWidget(m_pending, 1);
    auto *copy = new QPushButton(lower);
    m_buttons[QStringLiteral("copy")] = copy;
    pendingRow->addWidget(copy, 0, Qt::AlignTop);
    lowerLayout->addLayout(pendingRow);
    m_cli = new QLabel(lower);
    m_cli->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_cli->setWordWrap(true);
    lowerLayout->addWidget(m_cli);

    // The attitude actions two by two, the heading setting below them: the panel stays narrow
    // enough to sit beside the charts.
    auto *attitudeActions = new QGridLayout;
    int slot = 0;
    for (const char *key : {"ATT.RST.1", "ATT.RST.2", "ATT.RST.3", "ATT.RST.5"}) {
        auto *b = new QPushButton(lower);
        m_buttons[QLatin1String(key)] = b;
        connect(b, &QPushButton::clicked, this, [this, k = QString::fromLatin1(key)] { runAction(k); });
        attitudeActions->addWidget(b, slot / 2, slot % 2);
        ++slot;
    }
    attitudeActions->setColumnStretch(2, 1);
    lowerLayout->addLayout(attitudeActions);
    auto *actions = new QHBoxLayout;
    m_yawMode = new QComboBox(lower);
    m_yawDeg = new QDoubleSpinBox(lower);
    m_yawDeg->setRange(-180.0, 180.0);
    m_yawDeg->setDecimals(2);
    auto *yaw = new QPushButton(lower);
    m_buttons[QStringLiteral("YAW")] = yaw;
    connect(yaw, &QPushButton::clicked, this, [this] { runAction(QStringLiteral("YAW")); });
    actions->addWidget(m_yawMode);
    actions->addWidget(m_yawDeg);
    actions->addWidget(yaw);
    actions->addStretch(1);
    lowerLayout->addLayout(actions);
    m_replies = new QPlainTextEdit(lower);
    m_replies->setReadOnly(true);
    m_replies->setMaximumBlockCount(kMaxLogBlocks);
    lowerLayout->addWidget(m_replies, 1);
    // The table takes the height; the lower part keeps what its controls need.
    split->setStretchFactor(0, 4);
    split->setStretchFactor(1, 1);
    split->setCollapsible(0, false);
    split->setSizes({4000, 1}); // the lower part starts at its least height
    layout->addWidget(split, 1);

    connect(m_buttons[QStringLiteral("read")], &QPushButton::clicked, this, &ConfigPanel::readAll);
    connect(m_buttons[QStringLiteral("apply")], &QPushButton::clicked, this, &ConfigPanel::applyPending);
    connect(m_buttons[QStringLiteral("save")], &QPushButton::clicked, this, &ConfigPanel::saveToFlash);
    connect(m_buttons[QStringLiteral("reboot")], &QPushButton::clicked, this, &ConfigPanel::reboot);
    connect(m_buttons[QStringLiteral("freset")], &QPushButton::clicked, this, &ConfigPanel::factoryReset);
    connect(m_buttons[QStringLiteral("mounting")], &QPushButton::clicked, this, &ConfigPanel::chooseMounting);
    connect(copy, &QPushButton::clicked, this, &ConfigPanel::copyCliLine);

    connect(m_controller.get(), &ConfigurationController::configurationChanged, this,
            [this] {
                m_model->setConfiguration(m_controller->configuration());
                m_table->resizeColumnsToContents();
            });
    connect(m_model, &models::SettingsTableModel::pendingChanged, this, &ConfigPanel::updatePending);
    connect(m_controller.get(), &ConfigurationController::busyChanged, this, &ConfigPanel::updateState);
    connect(m_controller.get(), &ConfigurationController::commandSent, this,
            [this](const QString &c) { log(QStringLiteral("> ") + c); });
    connect(m_controller.get(), &ConfigurationController::replyReceived, this,
            [this](const QString &, const protocol::hipnuc::AsciiReply &r) {
                for (const auto &l : r.lines)
                    log(QStringLiteral("  ") + QString::fromStdString(l));
                if (r.ok())
                    log(tr("OK"));
                else
                    log(tr("%1: %2").arg(QString::fromLatin1(model::outcomeName(r.status)),
                                         QString::fromStdString(r.errorLine)),
                        true);
            });
    connect(m_controller.get(), &ConfigurationController::readFinished, this, [this](bool ok, const QString &why) {
        if (!ok)
            log(why, true);
        updateState();
    });
    connect(m_controller.get(), &ConfigurationController::applyFinished, this,
            [this](const ConfigurationController::ApplyReport &r) {
                for (const auto &c : r.results) {
                    const QString line = tr("%1=%2: %3 %4")
                                             .arg(c.key, c.requested, ConfigurationController::outcomeName(c.outcome), c.detail)
                                             .trimmed();
                    if (c.outcome == ConfigurationController::Outcome::Unconfirmed)
                        logUnsure(line);
                    else
                        log(line, c.outcome != ConfigurationController::Outcome::Verified);
                }
                if (!r.error.isEmpty())
                    log(r.error, true);
                updateState();
            });
    connect(m_controller.get(), &ConfigurationController::actionFinished, this,
            [this](const QString &key, bool ok, const QString &detail) {
                log(ok ? tr("%1 done").arg(key) : tr("%1 failed: %2").arg(key, detail), !ok);
                updateState();
            });
    retranslateUi();
    updateState();
}

ConfigPanel::~ConfigPanel() = default;

void ConfigPanel::setPortName(const QString &port)
{
    m_port = port;
    updatePending();
}

QPushButton *ConfigPanel::button(const QString &key) const
{
    const auto it = m_buttons.find(key);
    return it == m_buttons.end() ? nullptr : it->second;
}

void ConfigPanel::setColumnShown(int column, bool shown)
{
    m_table->setColumnHidden(column, !shown);
    QStringList list;
    for (int c : kOptionalColumns)
        if (!m_table->isColumnHidden(c))
            list << QString::number(c);
    QSettings().setValue(QLatin1String(kShownColumnsKey), list);
}

void ConfigPanel::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    QWidget::changeEvent(event);
}

void ConfigPanel::retranslateUi()
{
    m_buttons[QStringLiteral("read")]->setText(tr("Read all"));
    m_buttons[QStringLiteral("apply")]->setText(tr("Apply"));
    m_buttons[QStringLiteral("save")]->setText(tr("Save to flash"));
    m_buttons[QStringLiteral("reboot")]->setText(tr("Reboot"));
    m_buttons[QStringLiteral("freset")]->setText(tr("Factory reset…"));
    m_buttons[QStringLiteral("mounting")]->setText(tr("Mounting…"));
    m_buttons[QStringLiteral("copy")]->setText(tr("Copy as command line"));
    for (const auto &a : SettingCatalog::actions()) {
        const auto it = m_buttons.find(QLatin1String(a.key));
        if (it == m_buttons.end())
            continue;
        it->second->setText(SettingCatalog::label(a));
        it->second->setToolTip(SettingCatalog::conditions(a));
    }
    m_buttons[QStringLiteral("save")]->setToolTip(
        SettingCatalog::conditions(*SettingCatalog::findAction(QStringLiteral("SAVECONFIG"))));
    m_buttons[QStringLiteral("reboot")]->setToolTip(
        SettingCatalog::conditions(*SettingCatalog::findAction(QStringLiteral("REBOOT"))));
    m_buttons[QStringLiteral("freset")]->setToolTip(
        SettingCatalog::conditions(*SettingCatalog::findAction(QStringLiteral("FRESET"))));
    const int mode = m_yawMode->currentIndex();
    m_yawMode->clear();
    m_yawMode->addItem(tr("absolute"), 1);
    m_yawMode->addItem(tr("relative"), 0);
    m_yawMode->setCurrentIndex(mode < 0 ? 0 : mode);
    m_yawDeg->setSuffix(tr(" deg"));
    m_model->retranslate();
    updateState();
}

void ConfigPanel::updateState()
{
    const bool busy = m_controller->busy();
    const auto &id = m_controller->identity();
    const bool known = id.usable();
    m_identity->setText(known ? tr("%1, firmware %2, serial %3 (%4)")
                                    .arg(QString::fromStdString(id.productName),
                                         id.firmware ? QString::fromStdString(id.firmware->toString()) : QString(),
                                         QString::fromStdString(id.serial),
                                         QString::fromLatin1(model::familyName(id.family())))
                              : tr("Not read yet: press Read all."));
    m_buttons[QStringLiteral("read")]->setEnabled(!busy);
    m_buttons[QStringLiteral("apply")]->setEnabled(!busy && known && !m_model->pendingChanges().empty());
    for (const char *k : {"save", "reboot", "freset"})
        m_buttons[QLatin1String(k)]->setEnabled(!busy && known);
    const auto *urfr = SettingCatalog::find(QStringLiteral("IMU.URFR"));
    m_buttons[QStringLiteral("mounting")]->setEnabled(!busy && known
                                                      && SettingCatalog::availability(*urfr, id).available);
    for (const auto &a : SettingCatalog::actions()) {
        const auto it = m_buttons.find(QLatin1String(a.key));
        if (it == m_buttons.end() || QLatin1String(a.key) == QLatin1String("SAVECONFIG")
            || QLatin1String(a.key) == QLatin1String("REBOOT") || QLatin1String(a.key) == QLatin1String("FRESET"))
            continue;
        const auto av = known ? SettingCatalog::availability(a, id) : SettingCatalog::Availability{false, {}};
        it->second->setEnabled(!busy && av.available);
        it->second->setToolTip(av.available || av.reason.isEmpty()
                                   ? SettingCatalog::conditions(a)
                                   : av.reason + QLatin1Char('\n') + SettingCatalog::conditions(a));
    }
    const bool yaw = m_buttons[QStringLiteral("YAW")]->isEnabled();
    m_yawMode->setEnabled(yaw);
    m_yawDeg->setEnabled(yaw);
    m_table->setEnabled(!busy);
    updatePending();
}

void ConfigPanel::updatePending()
{
    const auto changes = m_model->pendingChanges();
    const auto plan = m_controller->plan(changes);
    QStringList lines;
    for (const auto &c : plan.commands)
        lines << QStringLiteral("> ") + QString::fromStdString(c.command.text);
    for (const auto &e : plan.errors)
        lines << tr("! %1").arg(e);
    m_pending->setPlainText(changes.empty() ? tr("No pending changes.") : lines.join(QLatin1Char('\n')));
    m_cli->setText(changes.empty() ? QString() : cliLine());
    m_cli->setVisible(!changes.empty()); // no empty line under "No pending changes"
    m_buttons[QStringLiteral("copy")]->setEnabled(!changes.empty());
    m_buttons[QStringLiteral("apply")]->setEnabled(!m_controller->busy() && m_controller->identity().usable()
                                                   && !changes.empty() && plan.ok());
    settings::DeviceConfiguration after = m_controller->configuration();
    for (const auto &c : plan.changes)
        after.values[c.key] = c.value;
    const auto bw = settings::BandwidthCalculator::evaluate(after);
    QString text = tr("Link: %1 of %2 bytes/s (%3 %) at %4 baud")
                       .arg(bw.bytesPerSecond, 0, 'f', 0)
                       .arg(bw.capacityBytesPerSecond, 0, 'f', 0)
                       .arg(bw.load * 100.0, 0, 'f', 0)
                       .arg(bw.baud);
    if (!bw.warning.isEmpty())
        text += QLatin1Char('\n') + bw.warning;
    m_link->setText(text);
    m_link->setStyleSheet(bw.fits ? QString() : QStringLiteral("color: #c62828"));
}

QString ConfigPanel::pendingText() const
{
    return m_pending->toPlainText();
}

QString ConfigPanel::cliLine() const
{
    const auto plan = m_controller->plan(m_model->pendingChanges());
    return ConfigurationController::cliLine(m_port.isEmpty() ? QStringLiteral("PORT") : m_port, plan.changes, false,
                                             false);
}

QString ConfigPanel::replyLog() const
{
    return m_replies->toPlainText();
}

QString ConfigPanel::linkText() const
{
    return m_link->text();
}

void ConfigPanel::log(const QString &line, bool error)
{
    if (!error) {
        m_replies->appendPlainText(line);
        return;
    }
    m_replies->appendHtml(QStringLiteral("<span style=\"color:#c62828\">%1</span>").arg(tr("✗ %1").arg(line).toHtmlEscaped()));
}

void ConfigPanel::logUnsure(const QString &line)
{
    m_replies->appendHtml(QStringLiteral("<span style=\"color:#b26a00\">%1</span>").arg(tr("? %1").arg(line).toHtmlEscaped()));
}

void ConfigPanel::showEvent(QShowEvent *event)
{
    QWidget::showEvent(event);
    if (!m_controller->busy() && !m_controller->identity().usable()
        && m_session.state() == device::SessionState::Connected)
        readAll();
}

void ConfigPanel::readAll()
{
    m_controller->readAll();
}

void ConfigPanel::applyPending()
{
    const auto changes = m_model->pendingChanges();
    if (changes.empty())
        return;
    settings::DeviceConfiguration after = m_controller->configuration();
    const auto plan = m_controller->plan(changes);
    for (const auto &c : plan.changes)
        after.values[c.key] = c.value;
    const auto bw = settings::BandwidthCalculator::evaluate(after);
    if (!bw.fits && !m_confirm(tr("Output too fast for the link"), bw.warning + QLatin1Char('\n') + tr("Apply anyway?")))
        return;
    m_controller->apply(changes);
}

void ConfigPanel::saveToFlash()
{
    m_controller->save();
}

void ConfigPanel::reboot()
{
    m_controller->reboot();
}

void ConfigPanel::factoryReset()
{
    const auto *a = SettingCatalog::findAction(QStringLiteral("FRESET"));
    if (!m_confirm(tr("Factory reset"), SettingCatalog::conditions(*a) + QLatin1Char('\n') + tr("Go ahead?")))
        return;
    m_controller->factoryReset();
}

void ConfigPanel::chooseMounting()
{
    const auto current = m_controller->configuration().value(QStringLiteral("IMU.URFR"));
    const int code = current ? current->toInt() : model::Mounting::kDefaultCode;
    MountingPicker picker(code, m_controller->identity().edition() == model::ManualEdition::V166, this);
    if (picker.exec() != QDialog::Accepted)
        return;
    if (!m_model->setPending(QStringLiteral("IMU.URFR"), picker.value()))
        log(m_model->lastError(), true);
}

void ConfigPanel::copyCliLine()
{
    QApplication::clipboard()->setText(cliLine());
}

void ConfigPanel::runAction(const QString &key)
{
    QString arg;
    if (key == QLatin1String("YAW"))
        arg = QStringLiteral("%1,%2").arg(m_yawMode->currentData().toInt()).arg(m_yawDeg->value());
    m_controller->runAction(key, arg);
}

} // namespace imudesk::ui
