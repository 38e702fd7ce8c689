#include "ui/firmware/firmware_update_dialog.h"

#include "core/firmware/can_firmware_updater.h"
#include "core/firmware/firmware_updater.h"
#include "protocol/ihex/intel_hex_loader.h"
#include "protocol/ihex/intel_hex_writer.h"
#include "sim/kboot_bootloader.h"
#include "common/work_place_size.h"

#include <QCanBus>
#include <QDir>
#include <QFile>
#include <QComboBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QGroupBox>
#include <QSpinBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QVBoxLayout>

namespace imudesk::ui {

namespace {

QString hex32(uint64_t v)
{
    return QStringLiteral("0x") + QString::number(qulonglong(v), 16).toUpper().rightJustified(8, QLatin1Char('0'));
}

QString versionText(const std::optional<model::FirmwareVersion> &v)
{
    return v ? QString::fromStdString(v->toString()) : FirmwareUpdateDialog::tr("unknown");
}

} // namespace

FirmwareUpdateDialog::FirmwareUpdateDialog(const QString &portName, int baud,
                                           const std::optional<model::DeviceIdentity> &identity, QWidget *parent)
    : QDialog(parent), m_port(portName), m_baud(baud), m_updater(new firmware::FirmwareUpdater(this)),
      m_canUpdater(new firmware::CanFirmwareUpdater(this))
{
    setWindowTitle(tr("Firmware update on %1").arg(portName));
    auto *form = new QFormLayout;

    m_link = new QComboBox(this);
    m_link->setObjectName(QStringLiteral("link"));
    m_link->addItem(tr("Serial port %1 (KBOOT bootloader)").arg(portName), int(Link::Serial));
    m_link->addItem(tr("CAN bus (CANopen SDO to object 0x1F51)"), int(Link::Can));
    m_link->setToolTip(tr("How the firmware reaches the module: its serial port, or a CAN adapter on the module's "
                          "CANopen bus"));
    form->addRow(tr("Link:"), m_link);

    auto *fileRow = new QHBoxLayout;
    m_file = new QLineEdit(this);
    m_file->setObjectName(QStringLiteral("file"));
    m_file->setReadOnly(true);
    m_file->setPlaceholderText(tr("Intel HEX (.hex) or raw binary (.bin)"));
    m_choose = new QPushButton(tr("Choose..."), this);
    m_choose->setObjectName(QStringLiteral("choose"));
    fileRow->addWidget(m_file, 1);
    fileRow->addWidget(m_choose);
    m_demoImage = new QPushButton(tr("Demo image"), this);
    m_demoImage->setObjectName(QStringLiteral("demoImage"));
    m_demoImage->setToolTip(tr("Simulated module only: write an application image of firmware 1.7.2 that the "
                               "simulated bootloader accepts, and choose it"));
    m_demoImage->hide();
    fileRow->addWidget(m_demoImage);
    form->addRow(tr("File:"), fileRow);

    m_binStart = new QLineEdit(QStringLiteral("0x8000"), this);
    m_binStart->setObjectName(QStringLiteral("binStart"));
    m_binStart->setToolTip(tr("A .bin file has no addresses: the flash address of its first byte"));
    form->addRow(tr("Start of a .bin:"), m_binStart);

    m_imageInfo = new QLabel(tr("no file chosen"), this);
    m_imageInfo->setObjectName(QStringLiteral("imageInfo"));
    m_imageInfo->setWordWrap(true);
    form->addRow(tr("Image:"), m_imageInfo);

    m_versions = new QLabel(this);
    m_versions->setObjectName(QStringLiteral("versions"));
    if (identity)
        m_versions->setText(tr("%1, firmware %2, bootloader %3")
                                .arg(QString::fromStdString(identity->productName), versionText(identity->firmware),
                                     versionText(identity->bootloader)));
    else
        m_versions->setText(tr("read when the update starts"));
    form->addRow(tr("Module:"), m_versions);

    m_state = new QLabel(tr("ready"), this);
    m_state->setObjectName(QStringLiteral("state"));
    form->addRow(tr("Step:"), m_state);

    m_progress = new QProgressBar(this);
    m_progress->setObjectName(QStringLiteral("progress"));
    m_progress->setRange(0, 1000);
    m_progress->setValue(0);
    form->addRow(tr("Progress:"), m_progress);

    m_rate = new QLabel(QStringLiteral("-"), this);
    m_rate->setObjectName(QStringLiteral("rate"));
    form->addRow(tr("Speed:"), m_rate);

    m_log = new QPlainTextEdit(this);
    m_log->setObjectName(QStringLiteral("log"));
    m_log->setReadOnly(true);
    m_log->setMaximumBlockCount(2000);

    m_outcome = new QLabel(this);
    m_outcome->setObjectName(QStringLiteral("outcome"));
    m_outcome->setWordWrap(true);

    m_start = new QPushButton(tr("Update"), this);
    m_start->setObjectName(QStringLiteral("start"));
    m_cancel = new QPushButton(tr("Close"), this);
    m_cancel->setObjectName(QStringLiteral("cancel"));
    auto *buttons = new QHBoxLayout;
    buttons->addStretch(1);
    buttons->addWidget(m_start);
    buttons->addWidget(m_cancel);

    auto *top = new QVBoxLayout(this);
    top->addLayout(form);
    top->addWidget(buildCanBox());
    top->addWidget(m_log, 1);
    top->addWidget(m_outcome);
    top->addLayout(buttons);
    fitWorkPlace(this, QSize(860, 660), parent);

    connect(m_choose, &QPushButton::clicked, this, &FirmwareUpdateDialog::chooseFile);
    connect(m_demoImage, &QPushButton::clicked, this, &FirmwareUpdateDialog::loadDemoImage);
    connect(m_start, &QPushButton::clicked, this, &FirmwareUpdateDialog::startUpdate);
    connect(m_cancel, &QPushButton::clicked, this, &FirmwareUpdateDialog::reject);
    connect(m_updater, &firmware::FirmwareUpdater::stateChanged, this, &FirmwareUpdateDialog::onState);
    connect(m_updater, &firmware::FirmwareUpdater::progressChanged, this, &FirmwareUpdateDialog::onProgress);
    connect(m_updater, &firmware::FirmwareUpdater::logMessage, this, &FirmwareUpdateDialog::onLog);
    connect(m_updater, &firmware::FirmwareUpdater::finished, this, &FirmwareUpdateDialog::onFinished);
    connect(m_canUpdater, &firmware::CanFirmwareUpdater::stateChanged, this, &FirmwareUpdateDialog::onState);
    connect(m_canUpdater, &firmware::CanFirmwareUpdater::progressChanged, this, &FirmwareUpdateDialog::onProgress);
    connect(m_canUpdater, &firmware::CanFirmwareUpdater::logMessage, this, &FirmwareUpdateDialog::onLog);
    connect(m_canUpdater, &firmware::CanFirmwareUpdater::finished, this, &FirmwareUpdateDialog::onFinished);
    connect(m_link, &QComboBox::currentIndexChanged, this, &FirmwareUpdateDialog::onLinkChanged);
    connect(m_canInterface, &QLineEdit::textChanged, this, &FirmwareUpdateDialog::updateButtons);
    connect(m_canPlugin, &QComboBox::currentIndexChanged, this, &FirmwareUpdateDialog::updateButtons);
    onLinkChanged();
}

QWidget *FirmwareUpdateDialog::buildCanBox()
{
    m_canBox = new QGroupBox(tr("CAN bus"), this);
    m_canBox->setObjectName(QStringLiteral("canBox"));
    auto *form = new QFormLayout(m_canBox);
    m_canPlugin = new QComboBox(m_canBox);
    m_canPlugin->setObjectName(QStringLiteral("canPlugin"));
    m_canPlugin->addItems(QCanBus::instance()->plugins());
    const int socketcan = m_canPlugin->findText(QStringLiteral("socketcan"));
    if (socketcan >= 0)
        m_canPlugin->setCurrentIndex(socketcan);
    m_canPlugin->setToolTip(tr("The Qt CAN bus plugin of the adapter (socketcan for Linux CAN interfaces)"));
    form->addRow(tr("Plugin:"), m_canPlugin);
    m_canInterface = new QLineEdit(QStringLiteral("can0"), m_canBox);
    m_canInterface->setObjectName(QStringLiteral("canInterface"));
    m_canInterface->setToolTip(tr("The adapter's interface name, e.g. can0"));
    form->addRow(tr("Interface:"), m_canInterface);
    m_canBitrate = new QSpinBox(m_canBox);
    m_canBitrate->setObjectName(QStringLiteral("canBitrate"));
    m_canBitrate->setRange(0, 1000000);
    m_canBitrate->setSingleStep(125000);
    m_canBitrate->setValue(500000);
    m_canBitrate->setSuffix(tr(" bit/s"));
    m_canBitrate->setSpecialValueText(tr("as configured"));
    m_canBitrate->setToolTip(tr("The bus bit rate in bit/s (the HiPNUC CANopen default is 500000 bit/s); 0 leaves the "
                                "interface's setting"));
    form->addRow(tr("Bit rate:"), m_canBitrate);
    m_canNode = new QSpinBox(m_canBox);
    m_canNode->setObjectName(QStringLiteral("canNode"));
    m_canNode->setRange(1, 127);
    m_canNode->setValue(8);
    m_canNode->setToolTip(tr("The module's CANopen node ID, 1..127 (HiPNUC default 8)"));
    form->addRow(tr("Node:"), m_canNode);
    return m_canBox;
}

void FirmwareUpdateDialog::setLink(Link link)
{
    m_link->setCurrentIndex(m_link->findData(int(link)));
}

FirmwareUpdateDialog::Link FirmwareUpdateDialog::link() const
{
    return Link(m_link->currentData().toInt());
}

void FirmwareUpdateDialog::setCanBus(const QString &plugin, const QString &interfaceName, int bitrate, int node)
{
    if (m_canPlugin->findText(plugin) < 0)
        m_canPlugin->addItem(plugin);
    m_canPlugin->setCurrentIndex(m_canPlugin->findText(plugin));
    m_canInterface->setText(interfaceName);
    m_canBitrate->setValue(bitrate);
    m_canNode->setValue(node);
}

void FirmwareUpdateDialog::onLinkChanged()
{
    const bool can = link() == Link::Can;
    m_canBox->setVisible(can);
    setWindowTitle(can ? tr("Firmware update over CAN") : tr("Firmware update on %1").arg(m_port));
    if (m_file && !m_file->text().isEmpty())
        loadFile(m_file->text()); // the checks differ per link
    updateButtons();
}

FirmwareUpdateDialog::~FirmwareUpdateDialog() = default;

bool FirmwareUpdateDialog::isRunning() const
{
    return m_updater->isRunning() || m_canUpdater->isRunning();
}

const firmware::UpdateFlow::Result &FirmwareUpdateDialog::result() const
{
    return m_updater->result();
}

const firmware::CanUpdateFlow::Result &FirmwareUpdateDialog::canResult() const
{
    return m_canUpdater->result();
}

void FirmwareUpdateDialog::setDemoImageOffered(bool offered)
{
    m_demoImage->setVisible(offered);
}

bool FirmwareUpdateDialog::loadDemoImage()
{
    protocol::ihex::FirmwareImage image;
    image.startAddress = 0x8000;
    image.data = sim::KbootBootloader::makeApplication("1.7.2", 96 * 1024);
    const std::string text = protocol::ihex::IntelHexWriter::write(image);
    m_demoImagePath = QDir::temp().filePath(QStringLiteral("imudesk-demo-firmware-1.7.2.hex"));
    QFile file(m_demoImagePath);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate)
        || file.write(text.data(), qint64(text.size())) != qint64(text.size())) {
        m_imageInfo->setText(tr("The demo image could not be written to %1: %2. Free some space in the temporary "
                                "folder and try again.")
                                 .arg(QDir::toNativeSeparators(m_demoImagePath), file.errorString()));
        return false;
    }
    file.close();
    return loadFile(m_demoImagePath);
}

void FirmwareUpdateDialog::chooseFile()
{
    const QString path = QFileDialog::getOpenFileName(this, tr("Choose the firmware"), QString(),
                                                      tr("Firmware (*.hex *.ihex *.bin);;All files (*)"));
    if (!path.isEmpty())
        loadFile(path);
}

bool FirmwareUpdateDialog::loadFile(const QString &path)
{
    m_image.reset();
    m_file->setText(path);
    std::optional<uint32_t> binStart;
    bool ok = false;
    const qulonglong start = m_binStart->text().trimmed().toULongLong(&ok, 0);
    if (ok && start <= 0xFFFFFFFFull)
        binStart = uint32_t(start);
    const auto r = protocol::ihex::IntelHexLoader::loadFile(path, binStart);
    if (!r.ok()) {
        m_imageInfo->setText(tr("refused: %1").arg(r.error));
        updateButtons();
        return false;
    }
    const QString e = link() == Link::Can ? firmware::CanUpdateFlow::checkImage(*r.image, std::nullopt)
                                          : firmware::UpdateFlow::checkImage(*r.image, std::nullopt);
    if (!e.isEmpty()) {
        m_imageInfo->setText(tr("refused: %1").arg(e));
        updateButtons();
        return false;
    }
    m_image = r.image;
    m_imageInfo->setText(tr("%1 bytes from %2 to %3, CRC-32 %4; target model: not recorded in the file")
                             .arg(m_image->size())
                             .arg(hex32(m_image->startAddress), hex32(m_image->endAddress() - 1),
                                  hex32(m_image->crc32())));
    updateButtons();
    return true;
}

void FirmwareUpdateDialog::setPortFree(bool free)
{
    m_portFree = free;
    if (free && m_startWhenFree) {
        m_startWhenFree = false;
        startUpdate();
        return;
    }
    updateButtons();
}

bool FirmwareUpdateDialog::startUpdate()
{
    if (!m_image || isRunning() || m_startWhenFree)
        return false;
    if (!m_portFree && link() == Link::Serial) {
        // The tab's link is still closing: the port would have two readers.
        m_startWhenFree = true;
        m_state->setText(tr("waiting for the tab to close the port..."));
        updateButtons();
        return true;
    }
    m_log->clear();
    m_outcome->clear();
    m_progress->setValue(0);
    m_lastWasCan = link() == Link::Can;
    if (m_lastWasCan) {
        firmware::CanUpdateFlow::Options co;
        co.node = uint8_t(m_canNode->value());
        const firmware::CanFirmwareUpdater::Bus bus{m_canPlugin->currentText(), m_canInterface->text().trimmed(),
                                                    m_canBitrate->value()};
        if (!m_canUpdater->start(bus, *m_image, co))
            return false;
        updateButtons();
        return true;
    }
    firmware::UpdateFlow::Options o;
    o.baud = m_baud;
    if (!m_updater->start(m_port, *m_image, o))
        return false;
    updateButtons();
    return true;
}

void FirmwareUpdateDialog::cancelUpdate()
{
    if (m_startWhenFree) {
        m_startWhenFree = false;
        m_state->setText(tr("ready"));
        updateButtons();
        return;
    }
    if (!isRunning())
        return;
    m_state->setText(tr("cancelling after the current packet..."));
    m_updater->cancel();
    m_canUpdater->cancel();
}

void FirmwareUpdateDialog::reject()
{
    if (isRunning()) {
        cancelUpdate(); // the dialog closes once the flow has stopped (onFinished)
        return;
    }
    QDialog::reject();
}

void FirmwareUpdateDialog::onState(int, const QString &name)
{
    m_state->setText(name);
}

void FirmwareUpdateDialog::onProgress(qulonglong done, qulonglong total, double bytesPerSecond, double secondsLeft)
{
    m_progress->setValue(total ? int(1000 * done / total) : 0);
    m_progress->setFormat(tr("%1 of %2 bytes").arg(done).arg(total));
    m_rate->setText(secondsLeft < 0 ? tr("%1 bytes/s").arg(qRound(bytesPerSecond))
                                    : tr("%1 bytes/s, %2 s left").arg(qRound(bytesPerSecond)).arg(qCeil(secondsLeft)));
}

void FirmwareUpdateDialog::onLog(const QString &line)
{
    m_log->appendPlainText(line);
}

void FirmwareUpdateDialog::onFinished(bool ok, const QString &message)
{
    if (m_lastWasCan) {
        const auto &cr = m_canUpdater->result();
        if (ok)
            m_versions->setText(tr("firmware %1 → %2 (new); verification: %3")
                                    .arg(versionText(cr.before), versionText(cr.after),
                                         cr.verifyMethod == QLatin1String("bootloader CRC")
                                             ? tr("CRC-32 reported by the bootloader")
                                             : tr("none by the bootloader; the application restarted")));
        m_outcome->setText(ok ? tr("Done: %1").arg(message) : tr("Not updated: %1").arg(message));
        updateButtons();
        Q_EMIT updateFinished(ok);
        return;
    }
    const auto &r = m_updater->result();
    if (ok && r.after)
        m_versions->setText(tr("%1, firmware %2 (new), bootloader %3")
                                .arg(QString::fromStdString(r.after->productName), versionText(r.after->firmware),
                                     versionText(r.after->bootloader)));
    m_outcome->setText(ok ? tr("Done: %1").arg(message) : tr("Not updated: %1").arg(message));
    updateButtons();
    Q_EMIT updateFinished(ok);
}

void FirmwareUpdateDialog::updateButtons()
{
    const bool running = isRunning() || m_startWhenFree;
    const bool canReady = link() != Link::Can || (!m_canPlugin->currentText().isEmpty() && !m_canInterface->text().trimmed().isEmpty());
    m_start->setEnabled(!running && m_image.has_value() && canReady);
    m_link->setEnabled(!running);
    m_canBox->setEnabled(!running);
    m_choose->setEnabled(!running);
    m_binStart->setEnabled(!running);
    m_cancel->setText(running ? tr("Cancel") : tr("Close"));
}

} // namespace imudesk::ui
