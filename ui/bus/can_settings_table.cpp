#include "bus/can_settings_table.h"

#include <QComboBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <limits>

namespace imudesk::ui {

using protocol::can::CanProtocol;

namespace {
const QColor kVerified(0x2e, 0x7d, 0x32);
const QColor kDiffers(0xc6, 0x28, 0x28);
const QColor kUnknown(0xb2, 0x6a, 0x00);
} // namespace

CanSettingsTable::CanSettingsTable(QWidget *parent)
    : QWidget(parent), m_table(new QTableWidget(this)), m_read(new QPushButton(this)), m_write(new QPushButton(this))
{
    m_table->setObjectName(QStringLiteral("canSettingsTable"));
    m_table->setColumnCount(ColumnCount);
    m_table->verticalHeader()->hide();
    m_table->setSelectionMode(QAbstractItemView::NoSelection);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->horizontalHeader()->setSectionResizeMode(SettingColumn, QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setSectionResizeMode(ModuleColumn, QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setSectionResizeMode(NewColumn, QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setSectionResizeMode(StatusColumn, QHeaderView::Stretch);
    m_read->setObjectName(QStringLiteral("canReadSettings"));
    m_write->setObjectName(QStringLiteral("canWriteSettings"));
    auto *buttons = new QHBoxLayout;
    buttons->addWidget(m_read);
    buttons->addWidget(m_write);
    buttons->addStretch();
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_table, 1);
    layout->addLayout(buttons);
    connect(m_read, &QPushButton::clicked, this, &CanSettingsTable::readAll);
    connect(m_write, &QPushButton::clicked, this, &CanSettingsTable::writeChanged);
    retranslateUi();
    updateButtons();
}

void CanSettingsTable::retranslateUi()
{
    m_table->setHorizontalHeaderLabels({tr("Setting"), tr("On the module"), tr("New value"), tr("Read back")});
    m_read->setText(tr("&Read from module"));
    m_read->setToolTip(tr("Read every setting the module can report (J1939 register reads, CANopen SDO uploads)"));
    m_write->setText(tr("&Write changed"));
    m_write->setToolTip(tr("Write the new values you changed; each is read back and marked verified or not"));
    // No word-wrapped text on this page: the dock's scroll area would size it by its preferred
    // height for the width and scroll where it need not.
    m_table->setToolTip(tr("The value on the module is read before anything is written; a write is read back."));
}

void CanSettingsTable::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange) {
        retranslateUi();
        rebuild(); // the labels, choices and notes are translated texts
    }
    QWidget::changeEvent(event);
}

void CanSettingsTable::setSession(device::CanSession *session)
{
    for (const auto &c : std::as_const(m_connections))
        disconnect(c);
    m_connections.clear();
    m_pending.clear();
    m_session = session;
    m_protocol = CanProtocol::Auto;
    if (session) {
        // Read once the protocol is known and the module has been heard (its node known): a
        // request sent while the bus still comes up would go unanswered.
        auto follow = [this] {
            if (!m_session || m_session->state() != device::SessionState::Connected || m_session->targetNode() < 0)
                return;
            const CanProtocol p = m_session->protocol();
            if (p == m_protocol)
                return;
            m_protocol = p;
            rebuild();
            readAll(); // the module's values first
        };
        m_connections << connect(session, &device::CanSession::requestFinished, this, &CanSettingsTable::onResult);
        m_connections << connect(session, &device::CanSession::protocolDetected, this, follow);
        m_connections << connect(session, &device::CanSession::stateChanged, this, follow);
        m_connections << connect(session, &device::CanSession::targetNodeChanged, this, follow);
        follow();
    }
    rebuild();
}

void CanSettingsTable::rebuild()
{
    const std::vector<Row> old = std::move(m_rows);
    m_rows.clear();
    m_table->clearContents();
    if (m_session && m_protocol != CanProtocol::Auto)
        for (protocol::can::CanSetting &s : m_session->settingsCatalogue())
            m_rows.push_back(Row{std::move(s), std::nullopt, false, nullptr});
    m_table->setRowCount(int(m_rows.size()));
    for (int i = 0; i < int(m_rows.size()); ++i) {
        Row &row = m_rows[size_t(i)];
        for (const Row &o : old)
            if (o.setting.name == row.setting.name)
                row.module = o.module;
        const protocol::can::CanSetting &s = row.setting;
        auto *label = new QTableWidgetItem(s.label);
        label->setToolTip(QStringLiteral("%1 (%2)%3").arg(s.name, s.range(), s.note.isEmpty() ? QString() : QStringLiteral(": ") + s.note));
        m_table->setItem(i, SettingColumn, label);
        auto *module = new QTableWidgetItem;
        module->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
        m_table->setItem(i, ModuleColumn, module);
        m_table->setItem(i, StatusColumn, new QTableWidgetItem);
        if (!s.readable) {
            module->setText(tr("not readable"));
            module->setForeground(palette().color(QPalette::Disabled, QPalette::Text));
            module->setToolTip(s.note);
        } else if (row.module) {
            module->setText(s.show(*row.module));
        }
        if (!s.writable) {
            row.editor = nullptr;
            continue;
        }
        if (!s.choices.empty()) {
            auto *combo = new QComboBox;
            for (const auto &[code, text] : s.choices)
                combo->addItem(text, code);
            connect(combo, &QComboBox::activated, this, [this, i] {
                m_rows[size_t(i)].edited = true;
                updateButtons();
            });
            row.editor = combo;
        } else {
            auto *spin = new QSpinBox;
            spin->setRange(int(std::min<uint32_t>(s.min, uint32_t(std::numeric_limits<int>::max()))),
                           int(std::min<uint32_t>(s.max, uint32_t(std::numeric_limits<int>::max()))));
            if (!s.unit.isEmpty())
                spin->setSuffix(QLatin1Char(' ') + s.unit);
            spin->setToolTip(tr("%1; %2").arg(s.range(), s.note.isEmpty() ? s.name : s.note));
            connect(spin, &QSpinBox::valueChanged, this, [this, i] {
                m_rows[size_t(i)].edited = true; // setEditorValue's own changes are not signalled
                updateButtons();
            });
            row.editor = spin;
        }
        if (row.module)
            setEditorValue(row, *row.module);
        m_table->setCellWidget(i, NewColumn, row.editor);
    }
    updateButtons();
}

int CanSettingsTable::rowOf(const QString &name) const
{
    for (int i = 0; i < int(m_rows.size()); ++i)
        if (m_rows[size_t(i)].setting.name == name)
            return i;
    return -1;
}

uint32_t CanSettingsTable::editorValue(const Row &row) const
{
    if (auto *combo = qobject_cast<QComboBox *>(row.editor))
        return combo->currentData().toUInt();
    if (auto *spin = qobject_cast<QSpinBox *>(row.editor))
        return uint32_t(spin->value());
    return 0;
}

void CanSettingsTable::setEditorValue(Row &row, uint32_t raw)
{
    if (auto *combo = qobject_cast<QComboBox *>(row.editor)) {
        if (const int i = combo->findData(raw); i >= 0)
            combo->setCurrentIndex(i);
    } else if (auto *spin = qobject_cast<QSpinBox *>(row.editor)) {
        const QSignalBlocker notAnEdit(spin); // the module's value, not a person's edit
        spin->setValue(int(std::min<uint32_t>(raw, uint32_t(std::numeric_limits<int>::max()))));
    }
}

bool CanSettingsTable::setNewValue(const QString &name, const QString &text)
{
    const int i = rowOf(name);
    if (i < 0 || !m_rows[size_t(i)].editor)
        return false;
    Row &row = m_rows[size_t(i)];
    const std::optional<uint32_t> raw = row.setting.parse(text, nullptr);
    if (!raw)
        return false;
    setEditorValue(row, *raw);
    row.edited = true;
    updateButtons();
    return true;
}

QString CanSettingsTable::moduleText(const QString &name) const
{
    const int i = rowOf(name);
    return i < 0 ? QString() : m_table->item(i, ModuleColumn)->text();
}

QString CanSettingsTable::statusText(const QString &name) const
{
    const int i = rowOf(name);
    return i < 0 ? QString() : m_table->item(i, StatusColumn)->text();
}

void CanSettingsTable::setStatus(int row, const QString &text, const QColor &colour, const QString &toolTip)
{
    QTableWidgetItem *item = m_table->item(row, StatusColumn);
    item->setText(text);
    item->setForeground(colour);
    item->setToolTip(toolTip.isEmpty() ? text : toolTip);
}

void CanSettingsTable::readAll()
{
    if (!m_session)
        return;
    for (int i = 0; i < int(m_rows.size()); ++i) {
        if (!m_rows[size_t(i)].setting.readable)
            continue;
        m_pending.insert(m_session->readSetting(m_rows[size_t(i)].setting), Pending{i, false, 0});
        setStatus(i, tr("reading…"), palette().color(QPalette::Disabled, QPalette::Text));
    }
    updateButtons();
}

void CanSettingsTable::writeChanged()
{
    if (!m_session)
        return;
    for (int i = 0; i < int(m_rows.size()); ++i) {
        Row &row = m_rows[size_t(i)];
        if (!row.edited || !row.editor)
            continue;
        const uint32_t raw = editorValue(row);
        row.edited = false;
        m_pending.insert(m_session->writeSetting(row.setting, raw), Pending{i, true, raw});
        setStatus(i, tr("writing…"), palette().color(QPalette::Disabled, QPalette::Text));
    }
    updateButtons();
}

void CanSettingsTable::onResult(const device::CanRequestResult &r)
{
    const auto it = m_pending.find(r.id);
    if (it == m_pending.end())
        return;
    const Pending p = it.value();
    m_pending.erase(it);
    if (p.row >= 0 && p.row < int(m_rows.size())) {
        Row &row = m_rows[size_t(p.row)];
        const protocol::can::CanSetting &s = row.setting;
        QTableWidgetItem *module = m_table->item(p.row, ModuleColumn);
        if (r.ok) {
            // A read: the module's value; a write: the value it took (read back, or for an
            // object with no read, the one its reply confirmed).
            const uint32_t value = p.write ? p.raw : r.value;
            row.module = value;
            if (s.readable && !p.write && s.words > 1) // a value of several registers (PNAME, R_H/R_L, SN)
                module->setText(s.showWords(std::vector<uint32_t>(r.values.begin(), r.values.end())));
            else if (s.readable)
                module->setText(s.show(value));
            if (!row.edited)
                setEditorValue(row, value);
            if (p.write)
                setStatus(p.row, s.readable ? tr("verified") : tr("confirmed by its reply (cannot be read back)"),
                          s.readable ? kVerified : kUnknown, r.message);
            else
                setStatus(p.row, QString(), palette().color(QPalette::Text));
        } else if (p.write && r.status == device::RequestStatus::Invalid && s.readable) {
            // The read-back found another value: the module holds that one.
            const QString held = s.show(r.value);
            row.module = r.value;
            module->setText(held);
            setStatus(p.row, tr("not taken: the module holds %1").arg(held), kDiffers, r.message);
        } else if (!p.write && !p.retried && r.status == device::RequestStatus::Timeout && m_session) {
            // Asked once more: a frame lost on a busy bus is not yet the module's silence.
            m_pending.insert(m_session->readSetting(s), Pending{p.row, false, 0, true});
            return;
        } else {
            setStatus(p.row, p.write ? tr("not confirmed: %1").arg(r.message) : tr("could not be read: %1").arg(r.message),
                      kUnknown, r.message);
        }
    }
    updateButtons();
    if (m_pending.isEmpty())
        Q_EMIT idle();
}

void CanSettingsTable::updateButtons()
{
    const bool ready = m_session && m_protocol != CanProtocol::Auto && m_pending.isEmpty();
    bool anyReadable = false, anyEdited = false;
    for (const Row &r : m_rows) {
        anyReadable |= r.setting.readable;
        anyEdited |= r.edited;
    }
    m_read->setEnabled(ready && anyReadable);
    m_write->setEnabled(ready && anyEdited);
}

} // namespace imudesk::ui
