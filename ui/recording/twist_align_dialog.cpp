#include "recording/twist_align_dialog.h"

#include "common/paint_helpers.h"
#include "common/work_place_size.h"
#include "record/capture_sample_stream.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPainter>
#include <QPainterPath>
#include <QProgressBar>
#include <QPushButton>
#include <QSplitter>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

namespace imudesk::ui {

// Helpers in a namespace of their own: ui is a unity build.
namespace twist_align_dialog_detail {
namespace {

using DeviceResult = TwistAlignDialog::DeviceResult;

enum class Stop { None, Cancelled, NoDeviceWithData, ReferenceWithoutData };

struct Run {
    std::vector<DeviceResult> devices;
    Stop stop = Stop::None;
    int reference = -1;
};

// A device's |gyro| on its common time (the stored offset not applied), within [fromNs, toNs]:
// what `imudesk-cli align` reads. False when cancelled.
bool readSeries(const QString &path, int64_t fromNs, int64_t toNs, const jobs::BackgroundJob::Context &job,
                const std::function<void(uint64_t)> &progress, clock::TwistSeries *s, QString *error)
{
    record::CaptureSampleStream stream;
    if (!stream.open(path, error))
        return true;
    uint64_t n = 0;
    while (stream.peek()) {
        const model::Sample x = stream.take();
        if ((++n & 1023) == 0) {
            progress(n);
            if (job.cancelled())
                return false;
        }
        if (!x.has(model::FieldGyr) || x.commonTimeNs == 0 || x.commonTimeNs < fromNs || x.commonTimeNs > toNs)
            continue;
        s->timeNs.push_back(x.commonTimeNs);
        s->gyroDps.push_back(std::sqrt(x.gyr.x * x.gyr.x + x.gyr.y * x.gyr.y + x.gyr.z * x.gyr.z));
    }
    return true;
}

// The search, in the worker thread: every device's series, then each aligned to the reference
// (referenceIndex -1: the first device with data).
Run search(const QString &folder, const record::SessionManifest &m, int referenceIndex, int64_t fromNs, int64_t toNs,
           const jobs::BackgroundJob::Context &job)
{
    Run run;
    const size_t n = m.devices.size();
    run.devices.resize(n);
    std::vector<clock::TwistSeries> series(n);
    // Progress: reading weighs by each capture's frames (session.json counts them), the
    // alignments take the last tenth.
    double total = 0;
    for (const auto &d : m.devices)
        total += double(std::max<quint64>(d.frames, 1));
    double done = 0;
    for (size_t i = 0; i < n; ++i) {
        const auto &d = m.devices[i];
        DeviceResult &r = run.devices[i];
        r.name = d.name;
        const double weight = double(std::max<quint64>(d.frames, 1));
        const auto progress = [&](uint64_t samples) {
            const double f = d.frames > 0 ? std::min(1.0, double(samples) / double(d.frames)) : 0.5;
            job.setProgress(0.9 * (done + weight * f) / total);
        };
        series[i].name = d.name.toStdString();
        if (!readSeries(QDir(folder).filePath(d.file), fromNs, toNs, job, progress, &series[i], &r.error)) {
            run.stop = Stop::Cancelled;
            return run;
        }
        r.samples = series[i].timeNs.size();
        if (!series[i].timeNs.empty())
            r.twists = clock::countTwists(series[i], clock::TwistAlignOptions{}.minPeakDps, series[i].timeNs.front(),
                                          series[i].timeNs.back());
        done += weight;
        job.setProgress(0.9 * done / total);
    }
    int ref = referenceIndex;
    if (ref < 0)
        for (size_t i = 0; i < n && ref < 0; ++i)
            if (!series[i].timeNs.empty())
                ref = int(i);
    if (ref < 0) {
        run.stop = Stop::NoDeviceWithData;
        return run;
    }
    run.reference = ref;
    run.devices[size_t(ref)].reference = true;
    if (series[size_t(ref)].timeNs.empty()) {
        run.stop = Stop::ReferenceWithoutData;
        return run;
    }
    for (size_t i = 0; i < n; ++i) {
        if (int(i) == ref || series[i].timeNs.empty())
            continue;
        if (job.cancelled()) {
            run.stop = Stop::Cancelled;
            return run;
        }
        run.devices[i].result = clock::alignByTwist(series[size_t(ref)], series[i]);
        job.setProgress(0.9 + 0.1 * double(i + 1) / double(n));
    }
    job.setProgress(1.0);
    return run;
}

QString ms(double ns, int decimals)
{
    return QString::number(ns / 1e6, 'f', decimals);
}

// A step of 1, 2 or 5 times a power of ten giving about `wanted` intervals over `span`.
double niceStep(double span, int wanted)
{
    if (!(span > 0))
        return 1;
    const double raw = span / std::max(1, wanted);
    const double p = std::pow(10.0, std::floor(std::log10(raw)));
    for (double k : {1.0, 2.0, 5.0, 10.0})
        if (raw <= k * p)
            return k * p;
    return 10 * p;
}

enum Column { ColDevice, ColOffset, ColUncertainty, ColCorrelation, ColTwists, ColStatus, ColumnCount };

} // namespace
} // namespace twist_align_dialog_detail

// (Each function below says `using namespace twist_align_dialog_detail;` itself: a directive
// here would reach the files after this one in a unity batch.)

// ---------------------------------------------------------------------------------------------
// CorrelationPlot

CorrelationPlot::CorrelationPlot(QWidget *parent) : QWidget(parent)
{
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
    setToolTip(tr("Normalised cross-correlation of each device's gyro magnitude with the reference's, against the "
                  "shift of its time (ms). The marker is the offset found; a good match peaks close to 1."));
}

void CorrelationPlot::setCurves(std::vector<Curve> curves)
{
    m_curves = std::move(curves);
    update();
}

void CorrelationPlot::clear()
{
    m_curves.clear();
    update();
}

void CorrelationPlot::setMinimumCorrelation(double c)
{
    m_minCorrelation = c;
    update();
}

QColor CorrelationPlot::curveColour(int i)
{
    static const QColor colours[] = {QColor(0x1f, 0x77, 0xb4), QColor(0xff, 0x7f, 0x0e), QColor(0x2c, 0xa0, 0x2c),
                                     QColor(0xd6, 0x27, 0x28), QColor(0x94, 0x67, 0xbd), QColor(0x8c, 0x56, 0x4b)};
    constexpr int n = int(sizeof(colours) / sizeof(colours[0]));
    return colours[((i % n) + n) % n];
}

QString CorrelationPlot::emptyText() const
{
    return tr("Find offsets to see how each device's gyro magnitude matches the reference's.");
}

void CorrelationPlot::paintEvent(QPaintEvent *)
{
    using namespace twist_align_dialog_detail;
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    const QPalette pal = palette();
    const QColor ink = pal.color(QPalette::Text);
    const QColor base = pal.color(QPalette::Base);
    p.fillRect(rect(), pal.color(QPalette::Window));
    const QFontMetrics fm(font());

    // The x range: every curve's lags (the searched range), else the default search.
    double x0 = std::numeric_limits<double>::infinity(), x1 = -x0;
    for (const Curve &c : m_curves)
        for (const auto &pt : c.points) {
            x0 = std::min(x0, pt.first);
            x1 = std::max(x1, pt.first);
        }
    if (!(x1 > x0)) {
        const double maxLagMs = double(clock::TwistAlignOptions{}.maxLagNs) / 1e6;
        x0 = -maxLagMs;
        x1 = maxLagMs;
    }
    constexpr double y0 = -1, y1 = 1;

    const QString yTitle = tr("Correlation");
    const QString xTitle = tr("Shift of the device's time (ms)");
    const int left = fm.height() + 6 + fm.horizontalAdvance(QStringLiteral("-0.5")) + 8;
    const int bottom = 2 * fm.height() + 10;
    const QRectF area(left, fm.height() / 2.0 + 4, std::max(10, width() - left - 12),
                      std::max(10.0, height() - bottom - fm.height() / 2.0 - 4));
    const auto X = [&](double v) { return area.left() + (v - x0) / (x1 - x0) * area.width(); };
    const auto Y = [&](double v) { return area.bottom() - (v - y0) / (y1 - y0) * area.height(); };

    p.fillRect(area, base);
    const QColor grid = mixColours(base, ink, 0.12);
    const QColor axis = mixColours(base, ink, 0.55);

    // Grid, ticks and their labels.
    p.setFont(font());
    for (double v = -1; v <= 1.0001; v += 0.5) {
        p.setPen(QPen(v == 0 ? axis : grid, 1));
        p.drawLine(QPointF(area.left(), Y(v)), QPointF(area.right(), Y(v)));
        p.setPen(ink);
        const QString label = QString::number(v, 'g', 2);
        p.drawText(QRectF(0, Y(v) - fm.height() / 2.0, area.left() - 4, fm.height()), Qt::AlignRight | Qt::AlignVCenter,
                   label);
    }
    const double step = niceStep(x1 - x0, std::max(2, int(area.width() / (fm.horizontalAdvance(QStringLiteral("-250")) * 2.5))));
    for (double v = std::ceil(x0 / step) * step; v <= x1 + step * 1e-6; v += step) {
        const double x = X(v);
        p.setPen(QPen(std::abs(v) < step * 1e-6 ? axis : grid, 1));
        p.drawLine(QPointF(x, area.top()), QPointF(x, area.bottom()));
        p.setPen(ink);
        const QString label = QString::number(std::abs(v) < step * 1e-6 ? 0.0 : v, 'g', 6);
        p.drawText(QRectF(x - 40, area.bottom() + 2, 80, fm.height()), Qt::AlignHCenter | Qt::AlignTop, label);
    }
    p.setPen(QPen(axis, 1));
    p.setBrush(Qt::NoBrush);
    p.drawRect(area);

    // Axis titles.
    p.setPen(ink);
    p.drawText(QRectF(area.left(), area.bottom() + fm.height() + 4, area.width(), fm.height()),
               Qt::AlignHCenter | Qt::AlignTop, xTitle);
    p.save();
    p.translate(2, area.center().y());
    p.rotate(-90);
    p.drawText(QRectF(-area.height() / 2, 0, area.height(), fm.height()), Qt::AlignHCenter | Qt::AlignTop, yTitle);
    p.restore();

    // The least correlation a match needs.
    if (m_minCorrelation > y0 && m_minCorrelation < y1) {
        p.setPen(QPen(mixColours(base, ink, 0.4), 1, Qt::DashLine));
        p.drawLine(QPointF(area.left(), Y(m_minCorrelation)), QPointF(area.right(), Y(m_minCorrelation)));
        p.setPen(mixColours(base, ink, 0.6));
        p.drawText(QRectF(area.left() + 4, Y(m_minCorrelation) + 1, area.width() / 2, fm.height()),
                   Qt::AlignLeft | Qt::AlignTop, tr("least correlation accepted"));
    }

    if (m_curves.empty()) {
        p.setPen(mixColours(base, ink, 0.6));
        p.drawText(area.adjusted(8, 8, -8, -8), Qt::AlignCenter | Qt::TextWordWrap, emptyText());
        return;
    }

    // The curves, clipped to the plot area, then the markers.
    p.save();
    p.setClipRect(area);
    for (size_t i = 0; i < m_curves.size(); ++i) {
        const Curve &c = m_curves[i];
        if (c.points.empty())
            continue;
        QPainterPath path;
        path.moveTo(X(c.points.front().first), Y(std::clamp(c.points.front().second, y0, y1)));
        for (size_t k = 1; k < c.points.size(); ++k)
            path.lineTo(X(c.points[k].first), Y(std::clamp(c.points[k].second, y0, y1)));
        p.setPen(QPen(curveColour(int(i)), c.aligned ? 2.0 : 1.2, c.aligned ? Qt::SolidLine : Qt::DashLine));
        p.setBrush(Qt::NoBrush);
        p.drawPath(path);
    }
    for (size_t i = 0; i < m_curves.size(); ++i) {
        const Curve &c = m_curves[i];
        if (!c.aligned)
            continue;
        const QColor colour = curveColour(int(i));
        const double x = X(c.offsetMs);
        p.setPen(QPen(colour, 1, Qt::DashLine));
        p.drawLine(QPointF(x, area.top()), QPointF(x, area.bottom()));
        p.setPen(QPen(colour.darker(130), 1.5));
        p.setBrush(colour);
        p.drawEllipse(QPointF(x, Y(std::clamp(c.correlation, y0, y1))), 4, 4);
    }
    p.restore();

    // The legend, in the lower right corner (the peaks are up).
    QStringList lines;
    for (const Curve &c : m_curves)
        lines << (c.aligned ? tr("%1: %2 ms, correlation %3").arg(c.name).arg(c.offsetMs, 0, 'f', 3).arg(c.correlation, 0, 'f', 3)
                            : tr("%1: not aligned").arg(c.name));
    int textWidth = 0;
    for (const QString &l : lines)
        textWidth = std::max(textWidth, fm.horizontalAdvance(l));
    const double swatch = 22, pad = 6;
    const double w = std::min(area.width() - 8, pad * 3 + swatch + textWidth + 2); // + 2: the advance rounds down
    const double h = pad * 2 + fm.height() * double(lines.size());
    const QRectF box(area.right() - w - 4, area.bottom() - h - 4, w, h);
    p.setPen(QPen(axis, 1));
    p.setBrush(base);
    p.drawRect(box);
    for (int i = 0; i < int(lines.size()); ++i) {
        const double y = box.top() + pad + fm.height() * (i + 0.5);
        p.setPen(QPen(curveColour(i), 2, m_curves[size_t(i)].aligned ? Qt::SolidLine : Qt::DashLine));
        p.drawLine(QPointF(box.left() + pad, y), QPointF(box.left() + pad + swatch, y));
        p.setPen(ink);
        p.drawText(QRectF(box.left() + pad * 2 + swatch, y - fm.height() / 2.0, w - pad * 3 - swatch, fm.height()),
                   Qt::AlignLeft | Qt::AlignVCenter, fm.elidedText(lines[i], Qt::ElideRight, int(w - pad * 3 - swatch)));
    }
}

// ---------------------------------------------------------------------------------------------
// TwistAlignDialog

TwistAlignDialog::TwistAlignDialog(const QString &sessionFolder, QWidget *parent) : QDialog(parent)
{
    using namespace twist_align_dialog_detail;
    setWindowTitle(tr("Twist to align"));
    m_instructions = new QLabel(
        tr("For modules on one fixture. While every device records, turn the fixture sharply (faster than "
           "60 deg/s) at least 3 times, at irregular intervals with a short rest between the turns, over at least "
           "10 s. Then open the recorded session here: ImuDesk cross-correlates the devices' gyro magnitudes and "
           "finds each device's constant time offset to the reference device."),
        this);
    m_instructions->setObjectName(QStringLiteral("instructions"));
    m_instructions->setWordWrap(true);

    m_folderEdit = new QLineEdit(this);
    m_folderEdit->setObjectName(QStringLiteral("folder"));
    m_folderEdit->setToolTip(tr("The folder of a recorded session: the one with session.json and a capture per device"));
    m_chooseFolder = new QPushButton(tr("Choose…"), this);
    m_chooseFolder->setObjectName(QStringLiteral("chooseFolder"));
    m_chooseFolder->setToolTip(tr("Open another recorded session"));
    m_reference = new QComboBox(this);
    m_reference->setObjectName(QStringLiteral("reference"));
    m_reference->setToolTip(tr("The device the others are aligned to: its offset is 0"));
    m_from = new QDoubleSpinBox(this);
    m_from->setObjectName(QStringLiteral("from"));
    m_from->setRange(0, 1e6);
    m_from->setDecimals(2);
    m_from->setSuffix(tr(" s"));
    m_from->setToolTip(tr("Start of the twists, in seconds since the recording began (0: from the start)"));
    m_to = new QDoubleSpinBox(this);
    m_to->setObjectName(QStringLiteral("to"));
    m_to->setRange(0, 1e6);
    m_to->setDecimals(2);
    m_to->setSuffix(tr(" s"));
    m_to->setSpecialValueText(tr("end"));
    m_to->setToolTip(tr("End of the twists, in seconds since the recording began (end: to the end of the session)"));

    m_table = new QTableWidget(0, ColumnCount, this);
    m_table->setObjectName(QStringLiteral("results"));
    m_table->setHorizontalHeaderLabels(
        {tr("Device"), tr("Offset (ms)"), tr("± (ms)"), tr("Correlation"), tr("Twists"), tr("Status")});
    m_table->horizontalHeaderItem(ColOffset)->setToolTip(
        tr("Added to the device's times to put them on the reference's, in milliseconds"));
    m_table->horizontalHeaderItem(ColUncertainty)->setToolTip(tr("One standard deviation of the offset, in milliseconds"));
    m_table->horizontalHeaderItem(ColCorrelation)->setToolTip(
        tr("Normalised correlation at the offset (-1 to 1); a good match is close to 1"));
    m_table->horizontalHeaderItem(ColTwists)->setToolTip(tr("Sharp turns found in the device's gyro magnitude"));
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->verticalHeader()->setVisible(false);
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->setWordWrap(true);
    m_table->setMinimumHeight(90);

    m_plot = new CorrelationPlot(this);
    m_plot->setObjectName(QStringLiteral("plot"));
    m_plot->setMinimumCorrelation(clock::TwistAlignOptions{}.minCorrelation);

    m_splitter = new QSplitter(Qt::Vertical, this);
    m_splitter->setObjectName(QStringLiteral("splitter"));
    m_splitter->addWidget(m_table);
    m_splitter->addWidget(m_plot);
    m_splitter->setChildrenCollapsible(false);
    m_splitter->setStretchFactor(0, 1);
    m_splitter->setStretchFactor(1, 2);

    m_progress = new QProgressBar(this);
    m_progress->setObjectName(QStringLiteral("progress"));
    m_progress->setRange(0, 1000);
    m_progress->setValue(0);
    m_status = new QLabel(this);
    m_status->setObjectName(QStringLiteral("status"));
    m_status->setWordWrap(true);
    m_status->setTextInteractionFlags(Qt::TextSelectableByMouse);

    auto *buttons = new QDialogButtonBox(this);
    m_find = buttons->addButton(tr("Find offsets"), QDialogButtonBox::ActionRole);
    m_find->setObjectName(QStringLiteral("find"));
    m_find->setToolTip(tr("Read the captures and cross-correlate each device's gyro magnitude with the reference's"));
    m_store = buttons->addButton(tr("Store offsets"), QDialogButtonBox::ApplyRole);
    m_store->setObjectName(QStringLiteral("store"));
    m_store->setToolTip(tr("Write the offsets found into the session's session.json; export and replay use them"));
    m_cancel = buttons->addButton(QDialogButtonBox::Close);
    m_cancel->setObjectName(QStringLiteral("cancel"));

    auto *folderRow = new QHBoxLayout;
    folderRow->addWidget(m_folderEdit, 1);
    folderRow->addWidget(m_chooseFolder);
    auto *windowRow = new QHBoxLayout;
    windowRow->addWidget(m_from);
    windowRow->addWidget(new QLabel(tr("to"), this));
    windowRow->addWidget(m_to);
    windowRow->addStretch(1);
    auto *form = new QFormLayout;
    form->addRow(tr("Session:"), folderRow);
    form->addRow(tr("Reference device:"), m_reference);
    form->addRow(tr("Twists from:"), windowRow);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_instructions);
    layout->addLayout(form);
    layout->addWidget(m_splitter, 1);
    layout->addWidget(m_progress);
    layout->addWidget(m_status);
    layout->addWidget(buttons);

    connect(m_folderEdit, &QLineEdit::editingFinished, this, [this] {
        if (m_folderEdit->text() != m_folder)
            setSessionFolder(m_folderEdit->text());
    });
    connect(m_chooseFolder, &QPushButton::clicked, this, &TwistAlignDialog::chooseFolder);
    connect(m_find, &QPushButton::clicked, this, &TwistAlignDialog::findOffsets);
    connect(m_store, &QPushButton::clicked, this, &TwistAlignDialog::storeOffsets);
    connect(m_cancel, &QPushButton::clicked, this, [this] {
        if (m_job.isRunning())
            cancelSearch();
        else
            reject();
    });
    connect(&m_job, &jobs::BackgroundJob::finished, this, &TwistAlignDialog::onFinished);
    m_poll.setInterval(100);
    connect(&m_poll, &QTimer::timeout, this, &TwistAlignDialog::pollProgress);

    fitWorkPlace(this, QSize(900, 640), parent);
    setSessionFolder(sessionFolder);
}

TwistAlignDialog::~TwistAlignDialog()
{
    // QDialog's destructor hides the window, which takes the focus from the folder field and
    // emits its editingFinished after this class is gone: its slot must not run then.
    disconnect(m_folderEdit, nullptr, this, nullptr);
    // m_job cancels and joins a running search.
}

void TwistAlignDialog::setSessionFolder(const QString &path)
{
    if (m_job.isRunning())
        return;
    m_folder = path;
    m_folderEdit->setText(path);
    clearResults();
    if (loadManifest()) {
        setStatus(m_manifest.devices.size() < 2
                      ? tr("The session in %1 has one device only: twist to align needs two or more devices recorded "
                           "together. Choose another session.")
                            .arg(QDir::toNativeSeparators(m_folder))
                      : tr("Press Find offsets to search the session's %1 devices for the twists.")
                            .arg(m_manifest.devices.size()),
                  m_manifest.devices.size() < 2);
    }
    updateButtons();
}

bool TwistAlignDialog::loadManifest()
{
    m_manifestOk = false;
    m_manifest = {};
    const QString previous = m_reference->currentText();
    const bool wasAutomatic = m_reference->currentIndex() <= 0;
    m_reference->clear();
    m_reference->addItem(tr("First device with gyroscope data"), -1);
    showDevices();
    const QString shown = QDir::toNativeSeparators(m_folder);
    if (m_folder.trimmed().isEmpty()) {
        setStatus(tr("Choose the folder of a recorded session (the folder with session.json)."), false);
        return false;
    }
    if (!QFileInfo(m_folder).isDir()) {
        setStatus(tr("%1 is not a folder. Choose the folder of a recorded session.").arg(shown), true);
        return false;
    }
    if (!record::SessionManifest::isSessionFolder(m_folder)) {
        setStatus(tr("%1 is not a recorded session: it has no session.json. Choose the folder a recording of several "
                     "devices wrote.")
                      .arg(shown),
                  true);
        return false;
    }
    QString error;
    if (!record::SessionManifest::load(m_folder, &m_manifest, &error)) {
        m_manifest = {};
        setStatus(tr("The session in %1 cannot be read (%2). Choose another session folder.").arg(shown, error), true);
        return false;
    }
    if (m_manifest.devices.empty()) {
        setStatus(tr("The session in %1 lists no device. Choose another session folder.").arg(shown), true);
        return false;
    }
    for (size_t i = 0; i < m_manifest.devices.size(); ++i)
        m_reference->addItem(m_manifest.devices[i].name, int(i));
    if (!wasAutomatic) {
        const int again = m_reference->findText(previous);
        if (again > 0)
            m_reference->setCurrentIndex(again);
    }
    m_manifestOk = true;
    showDevices();
    return true;
}

bool TwistAlignDialog::setReferenceDevice(const QString &name)
{
    if (name.isEmpty()) {
        m_reference->setCurrentIndex(0);
        return true;
    }
    const int i = m_reference->findText(name);
    if (i <= 0)
        return false;
    m_reference->setCurrentIndex(i);
    return true;
}

void TwistAlignDialog::setWindow(double fromS, double toS)
{
    m_from->setValue(fromS);
    m_to->setValue(toS);
}

void TwistAlignDialog::chooseFolder()
{
    const QString path =
        QFileDialog::getExistingDirectory(this, tr("Open a recorded session"), m_folder.isEmpty() ? QDir::homePath() : m_folder);
    if (!path.isEmpty())
        setSessionFolder(path);
}

bool TwistAlignDialog::anyAligned() const
{
    return std::any_of(m_results.begin(), m_results.end(), [](const DeviceResult &r) { return r.aligned(); });
}

QString TwistAlignDialog::statusText() const
{
    return m_status->text();
}

void TwistAlignDialog::setStatus(const QString &text, bool error)
{
    m_status->setText(text);
    QPalette pal = m_status->palette();
    pal.setColor(QPalette::WindowText, error ? QColor(0xc0, 0x20, 0x20) : palette().color(QPalette::WindowText));
    m_status->setPalette(pal);
    m_status->setProperty("error", error);
}

void TwistAlignDialog::updateButtons()
{
    const bool running = m_job.isRunning();
    m_find->setEnabled(!running && !m_folderEdit->text().trimmed().isEmpty());
    m_store->setEnabled(!running && anyAligned());
    m_cancel->setText(running ? tr("Cancel") : tr("Close"));
    m_cancel->setToolTip(running ? tr("Stop the search; nothing is changed") : tr("Close this window"));
}

void TwistAlignDialog::setBusy(bool busy)
{
    m_folderEdit->setEnabled(!busy);
    m_chooseFolder->setEnabled(!busy);
    m_reference->setEnabled(!busy);
    m_from->setEnabled(!busy);
    m_to->setEnabled(!busy);
    updateButtons();
}

void TwistAlignDialog::clearResults()
{
    m_results.clear();
    m_resultsFolder.clear();
    m_plot->clear();
    m_progress->setValue(0);
}

void TwistAlignDialog::showDevices()
{
    using namespace twist_align_dialog_detail;
    m_table->setRowCount(0);
    if (!m_manifestOk && m_manifest.devices.empty())
        return;
    m_table->setRowCount(int(m_manifest.devices.size()));
    for (int row = 0; row < int(m_manifest.devices.size()); ++row) {
        const auto &d = m_manifest.devices[size_t(row)];
        const bool stored = !d.offsetMethod.isEmpty();
        const QString status = stored ? tr("stored earlier (%1)").arg(d.offsetMethod) : tr("not searched yet");
        const QString cells[ColumnCount] = {d.name, stored ? ms(d.offsetNs, 3) : QStringLiteral("—"), QStringLiteral("—"),
                                            QStringLiteral("—"), QStringLiteral("—"), status};
        for (int c = 0; c < ColumnCount; ++c) {
            auto *item = new QTableWidgetItem(cells[c]);
            if (c != ColDevice && c != ColStatus)
                item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
            m_table->setItem(row, c, item);
        }
    }
    m_table->resizeColumnsToContents();
}

void TwistAlignDialog::findOffsets()
{
    using namespace twist_align_dialog_detail;
    if (m_job.isRunning())
        return;
    // A folder typed without leaving the field, or a session.json changed since: read it again.
    m_folder = m_folderEdit->text();
    clearResults();
    if (!loadManifest()) {
        updateButtons();
        Q_EMIT alignmentFinished(false);
        return;
    }
    if (m_manifest.devices.size() < 2) {
        setStatus(tr("The session in %1 has one device only: twist to align needs two or more devices recorded "
                     "together. Choose another session.")
                      .arg(QDir::toNativeSeparators(m_folder)),
                  true);
        updateButtons();
        Q_EMIT alignmentFinished(false);
        return;
    }
    const double fromS = m_from->value(), toS = m_to->value();
    if (toS > 0 && toS <= fromS) {
        setStatus(tr("The end of the twists (%1 s) must be later than their start (%2 s); set To to end for the whole "
                     "rest of the session.")
                      .arg(toS)
                      .arg(fromS),
                  true);
        updateButtons();
        Q_EMIT alignmentFinished(false);
        return;
    }
    const int64_t fromNs = m_manifest.startedHostNs + int64_t(std::llround(fromS * 1e9));
    const int64_t toNs = toS > 0 ? m_manifest.startedHostNs + int64_t(std::llround(toS * 1e9))
                                 : std::numeric_limits<int64_t>::max();
    const int referenceIndex = m_reference->currentData().toInt();
    const QString folder = m_folder;
    const record::SessionManifest manifest = m_manifest;
    m_cancelled = false;
    m_progress->setValue(0);
    setStatus(tr("Reading the captures of %1 devices…").arg(manifest.devices.size()), false);
    const bool launched = m_job.launch(
        QStringLiteral("imudesk-twist-align"),
        [this, folder, manifest, referenceIndex, fromNs, toNs](const jobs::BackgroundJob::Context &job) {
            Run run = search(folder, manifest, referenceIndex, fromNs, toNs, job);
            jobs::BackgroundJob::Outcome outcome;
            outcome.ok = run.stop == Stop::None;
            // Stored in the dialog's thread, after the worker has ended.
            outcome.apply = [this, folder, run = std::move(run)]() mutable {
                m_cancelled = run.stop == Stop::Cancelled;
                m_results = std::move(run.devices);
                m_resultsFolder = folder;
                if (run.stop == Stop::None)
                    return;
                const QString window = tr("Widen From and To, or set them to 0 and end for the whole session.");
                if (run.stop == Stop::Cancelled) {
                    m_results.clear();
                    setStatus(tr("Search cancelled; nothing was changed."), false);
                } else if (run.stop == Stop::NoDeviceWithData) {
                    setStatus(tr("No device of the session has gyroscope data with a common time in the searched "
                                 "part. %1 Devices need gyroscope output (HI91) while recording.")
                                  .arg(window),
                              true);
                } else {
                    setStatus(tr("The reference %1 has no gyroscope data with a common time in the searched part. "
                                 "Choose another reference device. %2")
                                  .arg(m_results[size_t(run.reference)].name, window),
                              true);
                }
            };
            return outcome;
        });
    if (!launched)
        return;
    setBusy(true);
    m_poll.start();
}

void TwistAlignDialog::cancelSearch()
{
    m_job.cancel();
}

void TwistAlignDialog::reject()
{
    cancelSearch(); // closed while searching (Esc, the title bar): the search stops
    QDialog::reject();
}

void TwistAlignDialog::pollProgress()
{
    m_progress->setValue(int(m_job.progress() * 1000));
}

void TwistAlignDialog::onFinished(bool ok, const QString &)
{
    m_poll.stop();
    setBusy(false);
    if (m_cancelled) {
        m_progress->setValue(0);
        showDevices();
    } else {
        m_progress->setValue(1000);
        showResults();
    }
    if (ok) {
        int others = 0, aligned = 0;
        QString reference;
        QStringList unreadable;
        for (const DeviceResult &r : m_results) {
            if (r.reference)
                reference = r.name;
            else
                ++others;
            if (r.aligned())
                ++aligned;
            if (!r.error.isEmpty())
                unreadable << r.name;
        }
        QString text;
        if (aligned > 0)
            text = tr("Aligned to %1: devices aligned %2 of %3. Check that the correlation is close to 1 and the ± column "
                      "small, then press Store offsets.")
                       .arg(reference)
                       .arg(aligned)
                       .arg(others);
        else
            text = tr("No device could be aligned to %1: see the Status column. Record the twists again (turn the "
                      "fixture sharply at least 3 times at irregular intervals while every device records), or set "
                      "From and To around the twists.")
                       .arg(reference);
        if (!unreadable.isEmpty())
            text += QLatin1Char(' ')
                + tr("The captures of %1 could not be read: check that the session folder holds every file session.json "
                     "names.")
                      .arg(unreadable.join(QStringLiteral(", ")));
        setStatus(text, aligned == 0 || !unreadable.isEmpty());
    }
    updateButtons();
    Q_EMIT alignmentFinished(anyAligned());
}

void TwistAlignDialog::showResults()
{
    using namespace twist_align_dialog_detail;
    m_table->setRowCount(int(m_results.size()));
    std::vector<CorrelationPlot::Curve> curves;
    const QColor good(0x2c, 0xa0, 0x2c), bad(0xd9, 0x7a, 0x00);
    for (int row = 0; row < int(m_results.size()); ++row) {
        const DeviceResult &r = m_results[size_t(row)];
        const clock::TwistAlignResult &a = r.result;
        QString cells[ColumnCount];
        cells[ColDevice] = r.name;
        cells[ColOffset] = cells[ColUncertainty] = cells[ColCorrelation] = QStringLiteral("—");
        cells[ColTwists] = r.samples > 0 ? QString::number(r.twists) : QStringLiteral("—");
        QColor colour;
        if (!r.error.isEmpty()) {
            cells[ColStatus] = tr("Capture unreadable: %1").arg(r.error);
            colour = bad;
        } else if (r.reference) {
            cells[ColOffset] = ms(0, 3);
            cells[ColStatus] = tr("reference");
        } else if (r.samples == 0) {
            cells[ColStatus] = tr("No gyroscope data with a common time in the searched part; left as it was.");
            colour = bad;
        } else {
            if (a.ok) {
                cells[ColOffset] = ms(a.offsetNs, 3);
                cells[ColUncertainty] = ms(a.uncertaintyNs, 3);
            }
            if (a.ok || a.correlation != 0)
                cells[ColCorrelation] = QString::number(a.correlation, 'f', 4);
            cells[ColTwists] = QString::number(a.twistsOther);
            cells[ColStatus] = a.ok ? tr("aligned") : tr("Not aligned: %1").arg(QString::fromStdString(a.whyNot));
            colour = a.ok ? good : bad;
            CorrelationPlot::Curve c;
            c.name = r.name;
            c.points = a.curve;
            c.aligned = a.ok;
            c.offsetMs = a.offsetNs / 1e6;
            c.correlation = a.correlation;
            if (!c.points.empty() || c.aligned)
                curves.push_back(std::move(c));
        }
        for (int col = 0; col < ColumnCount; ++col) {
            auto *item = new QTableWidgetItem(cells[col]);
            if (col != ColDevice && col != ColStatus)
                item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
            if (col == ColStatus) {
                item->setToolTip(cells[col]);
                if (colour.isValid())
                    item->setForeground(colour);
            }
            m_table->setItem(row, col, item);
        }
    }
    m_table->resizeColumnsToContents();
    m_table->resizeRowsToContents();
    m_plot->setCurves(std::move(curves));
}

bool TwistAlignDialog::storeOffsets()
{
    QString message;
    const auto failed = [&](const QString &text) {
        setStatus(text, true);
        Q_EMIT offsetsStored(false, text);
        return false;
    };
    if (m_job.isRunning())
        return failed(tr("The search is still running: wait for it to end, then store the offsets."));
    if (!anyAligned())
        return failed(tr("Nothing to store: no device is aligned. Press Find offsets first."));
    const QString shown = QDir::toNativeSeparators(m_resultsFolder);
    record::SessionManifest m;
    QString error;
    if (!record::SessionManifest::load(m_resultsFolder, &m, &error))
        return failed(tr("The session in %1 cannot be read any more (%2): nothing was stored. Check the folder, then "
                         "find the offsets again.")
                          .arg(shown, error));
    bool same = m.devices.size() == m_results.size();
    for (size_t i = 0; same && i < m.devices.size(); ++i)
        same = m.devices[i].name == m_results[i].name;
    if (!same)
        return failed(tr("The devices in %1 changed since the search: nothing was stored. Find the offsets again.")
                          .arg(QDir::toNativeSeparators(QDir(m_resultsFolder).filePath(QLatin1String(record::SessionManifest::kFileName)))));
    int stored = 0;
    for (size_t i = 0; i < m.devices.size(); ++i) {
        const DeviceResult &r = m_results[i];
        if (r.reference) {
            m.devices[i].offsetNs = 0;
            m.devices[i].offsetMethod = QStringLiteral("twist reference");
        } else if (r.aligned()) {
            m.devices[i].offsetNs = r.result.offsetNs;
            m.devices[i].offsetMethod = QStringLiteral("twist");
            ++stored;
        }
    }
    if (!m.save(m_resultsFolder, &error))
        return failed(tr("The offsets could not be stored (%1). Check that the session folder is writable, then press "
                         "Store offsets again.")
                          .arg(error));
    m_manifest = m;
    message = tr("Offsets stored in %2 (devices aligned: %1); export and replay of the session use them.")
                  .arg(stored)
                  .arg(QDir::toNativeSeparators(QDir(m_resultsFolder).filePath(QLatin1String(record::SessionManifest::kFileName))));
    setStatus(message, false);
    Q_EMIT offsetsStored(true, message);
    return true;
}

} // namespace imudesk::ui
