#include "charts/bandwidth_calculator.h"

#include "protocol/hipnuc/payloads.h"
#include "settings/setting_catalog.h"

#include <QComboBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QLabel>
#include <QLineEdit>
#include <QSpinBox>
#include <QVBoxLayout>

#include <cmath>

namespace imudesk::ui {

using Msg = protocol::hipnuc::Message;
using Calc = settings::BandwidthCalculator;

namespace {
constexpr Msg kMessages[] = {Msg::HI91, Msg::HI92, Msg::HI81, Msg::HI83, Msg::GGA, Msg::RMC, Msg::SXT};
}

BandwidthCalculator::BandwidthCalculator(QWidget *parent) : QWidget(parent)
{
    auto *layout = new QVBoxLayout(this);
    auto *form = new QFormLayout;
    m_baud = new QComboBox(this);
    for (int b : {4800, 9600, 19200, 38400, 57600, 115200, 230400, 256000, 460800, 921600})
        m_baud->addItem(QString::number(b), b);
    m_baud->setCurrentIndex(m_baud->findData(115200));
    form->addRow(tr("Baud rate:"), m_baud);
    m_map = new QLineEdit(QStringLiteral("0x000000FF"), this);
    form->addRow(tr("HI83 fields (MAP):"), m_map);
    layout->addLayout(form);

    auto *grid = new QGridLayout;
    grid->addWidget(new QLabel(tr("Message"), this), 0, 0);
    grid->addWidget(new QLabel(tr("Rate"), this), 0, 1);
    grid->addWidget(new QLabel(tr("Bytes per frame"), this), 0, 2);
    grid->addWidget(new QLabel(tr("Highest usual rate at this baud"), this), 0, 3);
    int row = 1;
    for (Msg m : kMessages) {
        grid->addWidget(new QLabel(QLatin1String(protocol::hipnuc::messageName(m)), this), row, 0);
        auto *spin = new QSpinBox(this);
        spin->setRange(0, 1000);
        spin->setSuffix(tr(" Hz"));
        spin->setSpecialValueText(tr("off"));
        m_rates[m] = spin;
        grid->addWidget(spin, row, 1);
        grid->addWidget(new QLabel(QString::number(Calc::frameBytes(m)), this), row, 2);
        m_max[m] = new QLabel(this);
        grid->addWidget(m_max[m], row, 3);
        connect(spin, &QSpinBox::valueChanged, this, &BandwidthCalculator::recompute);
        ++row;
    }
    layout->addLayout(grid);
    m_summary = new QLabel(this);
    m_warning = new QLabel(this);
    m_warning->setWordWrap(true);
    layout->addWidget(m_summary);
    layout->addWidget(m_warning);
    layout->addStretch(1);
    connect(m_baud, &QComboBox::currentIndexChanged, this, &BandwidthCalculator::recompute);
    connect(m_map, &QLineEdit::textChanged, this, &BandwidthCalculator::recompute);
    recompute();
}

void BandwidthCalculator::setConfiguration(const settings::DeviceConfiguration &config)
{
    if (const auto b = config.value(QStringLiteral("SERIAL.BAUD")))
        setBaud(b->toInt());
    if (const auto map = config.value(QStringLiteral("LOG.HI83.MAP")))
        m_map->setText(*map);
    for (const auto &d : settings::SettingCatalog::settings()) {
        if (d.kind != settings::SettingKind::MessageOutput)
            continue;
        const auto v = config.value(QLatin1String(d.key));
        const double period = v ? v->toDouble() : 0.0; // OFF and ONMARK read as 0
        setRate(d.message, period > 0 ? int(std::lround(1.0 / period)) : 0);
    }
}

void BandwidthCalculator::setBaud(int baud)
{
    const int i = m_baud->findData(baud);
    if (i >= 0)
        m_baud->setCurrentIndex(i);
}

void BandwidthCalculator::setRate(Msg m, int hz)
{
    m_rates.at(m)->setValue(hz);
}

void BandwidthCalculator::setHi83Map(uint32_t map)
{
    m_map->setText(QStringLiteral("0x%1").arg(map, 8, 16, QLatin1Char('0')));
}

void BandwidthCalculator::recompute()
{
    bool ok = false;
    const QString t = m_map->text().trimmed();
    uint32_t map = t.startsWith(QLatin1String("0x"), Qt::CaseInsensitive) ? t.mid(2).toUInt(&ok, 16) : t.toUInt(&ok);
    if (!ok || map == 0 || (map & ~protocol::hipnuc::Hi83::kSupportedMask))
        map = protocol::hipnuc::Hi83::kDefaultMap;
    const int baud = m_baud->currentData().toInt();
    std::vector<Calc::Stream> streams;
    for (Msg m : kMessages) {
        streams.push_back({m, double(m_rates.at(m)->value()), map});
        const int max = Calc::maxRateClass(m, baud, map);
        m_max.at(m)->setText(max > 0 ? tr("%1 Hz").arg(max) : tr("not even 1 Hz"));
    }
    m_result = Calc::evaluate(streams, baud);
    m_summary->setText(tr("%1 of %2 bytes/s (%3 % of the link)")
                           .arg(m_result.bytesPerSecond, 0, 'f', 0)
                           .arg(m_result.capacityBytesPerSecond, 0, 'f', 0)
                           .arg(m_result.load * 100.0, 0, 'f', 0));
    m_warning->setText(m_result.warning);
    m_warning->setStyleSheet(m_result.fits ? QString() : QStringLiteral("color: #c62828"));
    Q_EMIT resultChanged(m_result.fits);
}

QString BandwidthCalculator::summaryText() const
{
    return m_summary->text();
}

QString BandwidthCalculator::warningText() const
{
    return m_warning->text();
}

QString BandwidthCalculator::maxRateText(Msg m) const
{
    return m_max.at(m)->text();
}

} // namespace imudesk::ui
