#include "calibration/verify_module_wizard.h"

#include "calibration/calibration_report.h"
#include "common/work_place_size.h"
#include "device/device_session.h"
#include "verify/local_gravity.h"
#include "verify/report_json.h"

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QHeaderView>
#include <QJsonArray>
#include <QLabel>
#include <QPainter>
#include <QPlainTextEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QSettings>
#include <QTableWidget>
#include <QVBoxLayout>
#include <QWizardPage>

#include <cmath>

namespace imudesk::ui {

namespace {

// The up axis of each tile: the six faces, then six between them (as sim::Motion::Poses turns
// a module, so that a demo fills every tile).
constexpr double kTileUp[PoseTiles::kTiles][3] = {{0, 0, 1}, {1, 0, 0}, {0, 1, 0},  {0, 0, -1},  {-1, 0, 0},   {0, -1, 0},
                                                  {1, 1, 0}, {-1, 0, 1}, {0, 1, -1}, {1, -1, 1}, {-1, -1, -1}, {1, 0, -1}};
constexpr double kTileToleranceDeg = 25;

QString signedAxis(double v, QChar axis)
{
    return v > 0 ? QStringLiteral("+%1").arg(axis) : v < 0 ? QStringLiteral("−%1").arg(axis) : QString();
}

} // namespace

PoseTiles::PoseTiles(QWidget *parent) : QWidget(parent)
{
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
}

Eigen::Vector3d PoseTiles::tileUp(int tile)
{
    return Eigen::Vector3d(kTileUp[tile][0], kTileUp[tile][1], kTileUp[tile][2]).normalized();
}

int PoseTiles::tileOf(const Eigen::Vector3d &up)
{
    const Eigen::Vector3d u = up.normalized();
    int best = -1;
    double bestCos = std::cos(kTileToleranceDeg * M_PI / 180.0);
    for (int t = 0; t < kTiles; ++t)
        if (const double c = tileUp(t).dot(u); c > bestCos) {
            bestCos = c;
            best = t;
        }
    return best;
}

QString PoseTiles::tileName(int tile)
{
    QStringList parts;
    for (int a = 0; a < 3; ++a)
        if (const QString s = signedAxis(kTileUp[tile][a], QLatin1Char("XYZ"[a])); !s.isEmpty())
            parts << s;
    return tr("%1 up").arg(parts.join(QLatin1Char(' ')));
}

void PoseTiles::setDone(const std::array<bool, kTiles> &done, int current)
{
    if (done == m_done && current == m_current)
        return;
    m_done = done;
    m_current = current;
    update();
}

QSize PoseTiles::minimumSizeHint() const
{
    return QSize(6 * 70, 2 * 56);
}

void PoseTiles::paintEvent(QPaintEvent *)
{
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    const int cols = 6, rows = 2, gap = 6;
    const double w = (width() - gap * (cols + 1)) / double(cols), h = (height() - gap * (rows + 1)) / double(rows);
    for (int t = 0; t < kTiles; ++t) {
        const QRectF r(gap + (t % cols) * (w + gap), gap + (t / cols) * (h + gap), w, h);
        const QColor fill = m_done[size_t(t)] ? QColor(0x3c, 0xa0, 0x5a) : palette().color(QPalette::Base);
        p.setPen(QPen(t == m_current ? palette().color(QPalette::Highlight) : palette().color(QPalette::Mid),
                      t == m_current ? 3 : 1));
        p.setBrush(fill);
        p.drawRoundedRect(r, 6, 6);
        // The up axis as an arrow in the tile's upper half: its x and y leaning, z shown by length.
        const Eigen::Vector3d u = tileUp(t);
        const QPointF c(r.center().x(), r.top() + r.height() * 0.38);
        const double len = std::min(r.width(), r.height()) * 0.28;
        const QPointF tip = c + QPointF(u.x() * len, -(u.z() * 0.8 + u.y() * 0.4) * len);
        p.setPen(QPen(m_done[size_t(t)] ? Qt::white : palette().color(QPalette::Text), 2));
        p.drawLine(c, tip);
        p.drawEllipse(tip, 3, 3);
        p.drawText(QRectF(r.left(), r.top() + r.height() * 0.62, r.width(), r.height() * 0.36), Qt::AlignCenter,
                   tileName(t));
    }
}

VerifyModuleWizard::VerifyModuleWizard(device::DeviceSession &session, QWidget *parent)
    : QWizard(parent),
      m_session(session)
{
    setWindowTitle(tr("Verify module"));
    fitWorkPlace(this, QSize(980, 700), parent);

    auto *poses = new QWizardPage;
    poses->setTitle(tr("Turn the module through still poses"));
    auto *pl = new QVBoxLayout(poses);
    auto *guide = new QLabel(tr("Press Start, then hold the module still for 3 s in each orientation below (every face up "
                                "and down, then between them) and turn it to the next; the order does not matter. "
                                "9 poses are needed, 12 give the best figures. Keep it away from steel and magnets."));
    guide->setWordWrap(true);
    pl->addWidget(guide);
    auto *gravity = new QFormLayout;
    m_latitude = new QDoubleSpinBox;
    m_latitude->setObjectName(QStringLiteral("verifyLatitude"));
    m_latitude->setRange(-90, 90);
    m_latitude->setDecimals(2);
    m_latitude->setSuffix(QStringLiteral(" °"));
    m_latitude->setToolTip(tr("The bench's latitude (degrees, north positive): its normal gravity, WGS 84"));
    m_height = new QDoubleSpinBox;
    m_height->setObjectName(QStringLiteral("verifyHeight"));
    m_height->setRange(-500, 9000);
    m_height->setDecimals(0);
    m_height->setSuffix(QStringLiteral(" m"));
    m_height->setToolTip(tr("The bench's height above the ellipsoid (metres)"));
    m_gravityKnown = new QCheckBox(tr("Measured gravity:"));
    m_gravity = new QDoubleSpinBox;
    m_gravity->setObjectName(QStringLiteral("verifyGravity"));
    m_gravity->setRange(9.7, 9.9);
    m_gravity->setDecimals(5);
    m_gravity->setSuffix(QStringLiteral(" m/s²"));
    m_gravity->setToolTip(tr("The bench's gravity from a survey (m/s²), instead of latitude and height"));
    const QSettings settings;
    m_latitude->setValue(settings.value(QStringLiteral("verify/latitude"), 45.0).toDouble());
    m_height->setValue(settings.value(QStringLiteral("verify/height"), 0.0).toDouble());
    m_gravityKnown->setChecked(settings.value(QStringLiteral("verify/gravityKnown"), false).toBool());
    m_gravity->setValue(settings.value(QStringLiteral("verify/gravity"), verify::kStandardGravity).toDouble());
    auto *place = new QHBoxLayout;
    place->addWidget(m_latitude);
    place->addWidget(new QLabel(tr("height")));
    place->addWidget(m_height);
    place->addSpacing(16);
    place->addWidget(m_gravityKnown);
    place->addWidget(m_gravity);
    place->addStretch();
    gravity->addRow(tr("Bench latitude:"), place);
    pl->addLayout(gravity);
    auto syncGravity = [this] {
        m_gravity->setEnabled(m_gravityKnown->isChecked());
        m_latitude->setEnabled(!m_gravityKnown->isChecked());
        m_height->setEnabled(!m_gravityKnown->isChecked());
    };
    connect(m_gravityKnown, &QCheckBox::toggled, this, syncGravity);
    syncGravity();

    m_tiles = new PoseTiles;
    m_tiles->setObjectName(QStringLiteral("poseTiles"));
    pl->addWidget(m_tiles, 1);
    m_hold = new QLabel(tr("Press Start."));
    m_hold->setObjectName(QStringLiteral("holdStill"));
    QFont big = m_hold->font();
    big.setPointSizeF(big.pointSizeF() * 1.4);
    m_hold->setFont(big);
    m_tally = new QLabel;
    m_tally->setObjectName(QStringLiteral("poseTally"));
    m_tally->setWordWrap(true);
    m_progress = new QProgressBar;
    m_progress->setRange(0, PoseTiles::kTiles);
    m_progress->setFormat(tr("%v of 12 poses"));
    m_start = new QPushButton(tr("Start"));
    m_start->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_R));
    m_start->setToolTip(tr("Start recording the poses (Ctrl+R)"));
    m_stop = new QPushButton(tr("Stop"));
    m_stop->setEnabled(false);
    auto *row = new QHBoxLayout;
    row->addWidget(m_start);
    row->addWidget(m_stop);
    row->addWidget(m_progress, 1);
    pl->addLayout(row);
    pl->addWidget(m_hold);
    pl->addWidget(m_tally);
    setPage(PosesPage, poses);

    auto *result = new QWizardPage;
    result->setTitle(tr("Result"));
    auto *rl = new QVBoxLayout(result);
    m_verdict = new QLabel;
    m_verdict->setObjectName(QStringLiteral("verifyVerdict"));
    m_verdict->setFont(big);
    m_verdict->setWordWrap(true);
    rl->addWidget(m_verdict);
    m_table = new QTableWidget(0, 5);
    m_table->setObjectName(QStringLiteral("verifyFigures"));
    m_table->setHorizontalHeaderLabels({tr("Figure"), tr("Value"), tr("95 % bound"), tr("Limits (pass / fail)"), tr("Verdict")});
    m_table->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
    for (int c = 1; c < 5; ++c)
        m_table->horizontalHeader()->setSectionResizeMode(c, QHeaderView::ResizeToContents);
    m_table->verticalHeader()->hide();
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSizeAdjustPolicy(QAbstractScrollArea::AdjustToContents);
    m_table->setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    rl->addWidget(m_table);
    m_reasons = new QPlainTextEdit;
    m_reasons->setObjectName(QStringLiteral("verifyReasons"));
    m_reasons->setReadOnly(true);
    rl->addWidget(m_reasons, 1);
    auto *bottom = new QHBoxLayout;
    m_saved = new QLabel;
    m_saved->setWordWrap(true);
    m_pdf = new QPushButton(tr("Export report (PDF)…"));
    bottom->addWidget(m_saved, 1);
    bottom->addWidget(m_pdf);
    rl->addLayout(bottom);
    setPage(ResultPage, result);

    connect(m_start, &QPushButton::clicked, this, &VerifyModuleWizard::start);
    connect(m_stop, &QPushButton::clicked, this, &VerifyModuleWizard::stop);
    connect(m_pdf, &QPushButton::clicked, this, &VerifyModuleWizard::exportPdf);
    m_clock.setInterval(kClockMs);
    connect(&m_clock, &QTimer::timeout, this, &VerifyModuleWizard::poll);
    clearRecording();
    refreshTally();
}

verify::CheckOptions VerifyModuleWizard::options() const
{
    verify::CheckOptions o;
    o.gravityMs2 = m_gravityKnown->isChecked() ? m_gravity->value()
                                               : verify::normalGravity(m_latitude->value(), m_height->value());
    return o;
}

void VerifyModuleWizard::rememberGravity()
{
    QSettings settings;
    settings.setValue(QStringLiteral("verify/latitude"), m_latitude->value());
    settings.setValue(QStringLiteral("verify/height"), m_height->value());
    settings.setValue(QStringLiteral("verify/gravityKnown"), m_gravityKnown->isChecked());
    settings.setValue(QStringLiteral("verify/gravity"), m_gravity->value());
}

void VerifyModuleWizard::clearRecording()
{
    m_input = verify::MotionInput{};
    m_rows = calib::SampleTable{};
    m_rows.columns = {QStringLiteral("t"), QStringLiteral("acc_x"), QStringLiteral("acc_y"), QStringLiteral("acc_z"),
                      QStringLiteral("gyr_x"), QStringLiteral("gyr_y"), QStringLiteral("gyr_z"), QStringLiteral("mag_x"),
                      QStringLiteral("mag_y"), QStringLiteral("mag_z")};
    m_report = verify::CheckReport{};
    m_found = FoundPoses{};
}

void VerifyModuleWizard::start()
{
    clearRecording();
    m_seq = m_session.store().totalAppended();
    m_recording = true;
    m_start->setEnabled(false);
    m_stop->setEnabled(true);
    m_clock.start();
    rememberGravity();
    refreshTally();
}

void VerifyModuleWizard::stop()
{
    poll();
    m_recording = false;
    m_clock.stop();
    m_start->setEnabled(true);
    m_stop->setEnabled(false);
    refreshTally();
}

void VerifyModuleWizard::addSamples(const std::vector<model::Sample> &samples)
{
    for (const model::Sample &s : samples) {
        const size_t before = m_input.samples().size();
        m_input.add(s);
        if (m_input.samples().size() == before || m_rows.rows.size() >= CalibrationRunSaver::kMaxRows)
            continue;
        const verify::MotionSample &m = m_input.samples().back();
        m_rows.rows.push_back({m.tS, m.acc.x(), m.acc.y(), m.acc.z(), m.gyr.x(), m.gyr.y(), m.gyr.z(), m.mag.x(), m.mag.y(),
                               m.mag.z()});
    }
    refreshTally();
}

void VerifyModuleWizard::poll()
{
    if (!m_recording)
        return;
    addSamples(m_session.store().since(m_seq, SIZE_MAX, &m_seq));
    if (m_input.full()) {
        stop();
        m_hold->setText(tr("The recording is full (%1 samples): press Next.").arg(m_input.samples().size()));
    }
}

void VerifyModuleWizard::refreshTally()
{
    const auto &samples = m_input.samples();
    // The poses so far: re-found on the clock, but never for more than a twentieth of the
    // time (a long recording takes longer to search).
    if (!samples.empty() && (!m_found.valid || m_found.since.elapsed() >= 20 * m_found.costMs || !m_recording)) {
        QElapsedTimer cost;
        cost.start();
        m_found.poses = verify::findStillPoses(samples, options());
        m_found.costMs = cost.elapsed();
        m_found.since.start();
        m_found.valid = true;
    } else if (samples.empty()) {
        m_found = FoundPoses{};
    }
    std::vector<verify::Pose> found = m_found.poses;
    std::array<bool, PoseTiles::kTiles> done{};
    int distinct = verify::groupPoses(found, options().samePoseDeg);
    for (const verify::Pose &p : found)
        if (const int t = PoseTiles::tileOf(p.acc); t >= 0)
            done[size_t(t)] = true;
    // Still now? The last stillWindowS of samples against the stillness limits.
    int current = -1;
    double stillFor = 0;
    if (m_recording && samples.size() > 10) {
        const double end = samples.back().tS;
        size_t k = samples.size();
        Eigen::Vector3d lastAcc = samples.back().acc;
        const verify::CheckOptions o = options();
        while (k > 0 && (samples[k - 1].gyr - samples.back().gyr).norm() < 6 * o.maxGyroStdDps
               && (samples[k - 1].acc - lastAcc).norm() < 6 * o.maxAccStdG && samples[k - 1].gyr.norm() < 3 * o.maxGyroMeanDps)
            --k;
        stillFor = k < samples.size() ? end - samples[k].tS : 0;
        current = PoseTiles::tileOf(lastAcc);
    }
    m_tiles->setDone(done, current);
    int tilesDone = 0;
    for (bool d : done)
        tilesDone += d;
    m_progress->setValue(tilesDone);
    if (!m_recording && samples.empty())
        m_hold->setText(tr("Press Start."));
    else if (!m_recording)
        m_hold->setText(distinct >= options().minPoses ? tr("Recorded: press Next for the result.")
                                                       : tr("Stopped: press Start to record again, or Next to judge what was "
                                                            "recorded."));
    else if (stillFor <= 0.2)
        m_hold->setText(tr("Turn the module to the next pose."));
    else if (stillFor < kHoldS)
        m_hold->setText(tr("Hold still: %1 s").arg(kHoldS - stillFor, 0, 'f', 1));
    else
        m_hold->setText(tr("Pose recorded: turn to the next."));
    m_tally->setText(tr("%1 distinct poses held (9 needed, 12 suggested); %2 s recorded, %3 samples.")
                         .arg(distinct)
                         .arg(samples.empty() ? 0.0 : samples.back().tS - samples.front().tS, 0, 'f', 1)
                         .arg(samples.size()));
}

bool VerifyModuleWizard::validateCurrentPage()
{
    if (currentId() == PosesPage) {
        if (m_recording)
            stop();
        if (m_input.samples().empty()) {
            m_hold->setText(tr("Nothing recorded yet: press Start and turn the module through the poses."));
            return false;
        }
    }
    return QWizard::validateCurrentPage();
}

void VerifyModuleWizard::initializePage(int id)
{
    if (id == ResultPage)
        showResult();
    QWizard::initializePage(id);
}

void VerifyModuleWizard::analyse()
{
    // The bench's gravity the result was judged with is the next run's too (also when the
    // samples came without Start, from a file or a test).
    rememberGravity();
    m_report = verify::checkModule(m_input.samples(), options());
}

void VerifyModuleWizard::showResult()
{
    analyse();
    const verify::CheckReport &r = m_report;
    const verify::Limits &l = options().limits;
    m_verdict->setText(tr("Verdict: %1").arg(verify::verdictText(r.verdict)));
    const char *colour = r.verdict == verify::Verdict::Pass ? "#2e7d32"
        : r.verdict == verify::Verdict::Fail                ? "#c62828"
                                                            : "#a66400";
    m_verdict->setStyleSheet(QStringLiteral("color: %1").arg(QLatin1String(colour)));
    struct Row {
        const char *key;
        QString name, unit;
        int decimals;
        bool judged;
        QString value, bound;
        verify::Limit limit;
    };
    auto axes = [](const Eigen::Vector3d &v, int decimals) {
        return QStringLiteral("%1, %2, %3").arg(v.x(), 0, 'f', decimals).arg(v.y(), 0, 'f', decimals).arg(v.z(), 0, 'f', decimals);
    };
    auto row3 = [&](const char *key, const QString &name, const QString &unit, int d, const verify::Figure3 &f, const verify::Limit &lim) {
        return Row{key, name, unit, d, f.judged, f.judged ? axes(f.value, d) : f.why, f.judged ? axes(1.959964 * f.sigma, d) : QString(), lim};
    };
    auto row1 = [&](const char *key, const QString &name, const QString &unit, int d, const verify::Figure &f, const verify::Limit &lim) {
        return Row{key, name, unit, d, f.judged, f.judged ? QString::number(f.value, 'f', d) : f.why,
                   f.judged ? QString::number(f.bound95(), 'f', d) : QString(), lim};
    };
    const std::vector<Row> rows = {
        row3("acc_bias_mg", tr("Accelerometer bias (mg; X, Y, Z)"), QStringLiteral("mg"), 2, r.accBiasMg, l.accBiasMg),
        row3("acc_scale_error_pct", tr("Accelerometer scale error (%; X, Y, Z)"), QStringLiteral("%"), 3, r.accScalePct, l.accScalePct),
        row1("acc_misalignment_deg", tr("Accelerometer misalignment, largest (°)"), QStringLiteral("°"), 3, r.accMisalignmentDeg, l.accMisalignmentDeg),
        row3("gyro_bias_dps", tr("Gyro bias (°/s; X, Y, Z)"), QStringLiteral("°/s"), 3, r.gyroBiasDps, l.gyroBiasDps),
        row3("gyro_scale_error_pct", tr("Gyro scale error (%; X, Y, Z)"), QStringLiteral("%"), 3, r.gyroScalePct, l.gyroScalePct),
        row1("gyro_misalignment_deg", tr("Gyro misalignment, largest (°)"), QStringLiteral("°"), 3, r.gyroMisalignmentDeg,
             l.gyroMisalignmentDeg),
        row1("roll_deg", tr("Roll error (°)"), QStringLiteral("°"), 3, r.rollErrDeg, l.tiltDeg),
        row1("pitch_deg", tr("Pitch error (°)"), QStringLiteral("°"), 3, r.pitchErrDeg, l.tiltDeg),
        row1("heading_deg", tr("Heading error (°)"), QStringLiteral("°"), 2, r.headingErrDeg, l.headingDeg),
        row1("dynamic_rms_deg", tr("Attitude error while moving, RMS (°)"), QStringLiteral("°"), 2, r.dynamicRmsDeg, l.dynamicRmsDeg),
        row1("lag_ms", tr("Attitude lag (ms)"), QStringLiteral("ms"), 1, r.dynamicLagMs, l.lagMs),
    };
    m_table->setRowCount(int(rows.size()));
    for (int i = 0; i < int(rows.size()); ++i) {
        const Row &row = rows[size_t(i)];
        m_table->setItem(i, 0, new QTableWidgetItem(row.name));
        auto *value = new QTableWidgetItem(row.value);
        value->setToolTip(row.value);
        m_table->setItem(i, 1, value);
        m_table->setItem(i, 2, new QTableWidgetItem(row.judged ? QStringLiteral("± ") + row.bound : QString()));
        m_table->setItem(i, 3, new QTableWidgetItem(QStringLiteral("%1 / %2").arg(row.limit.pass).arg(row.limit.fail)));
        const verify::Verdict v = r.figureVerdict(QLatin1String(row.key));
        auto *verdict = new QTableWidgetItem(verify::verdictText(v));
        verdict->setForeground(v == verify::Verdict::Pass ? QColor(0x2e, 0x7d, 0x32)
                               : v == verify::Verdict::Fail ? QColor(0xc6, 0x28, 0x28)
                                                             : QColor(0xa6, 0x64, 0x00));
        m_table->setItem(i, 4, verdict);
    }
    // Every row as tall as one line, the table as tall as its rows: the reasons below get the rest.
    m_table->verticalHeader()->setSectionResizeMode(QHeaderView::Fixed);
    m_table->verticalHeader()->setDefaultSectionSize(m_table->fontMetrics().height() + 8);
    m_table->setFixedHeight(m_table->horizontalHeader()->height() + int(rows.size()) * m_table->verticalHeader()->defaultSectionSize()
                            + 2 * m_table->frameWidth() + 2);
    m_reasons->setPlainText(tr("%1 still intervals, %2 distinct poses, gravity %3 m/s²")
                                .arg(r.poses.size())
                                .arg(r.distinctPoses)
                                .arg(r.gravityG * model::kGravity, 0, 'f', 5)
                            + QStringLiteral("\n") + r.reasons.join(QLatin1Char('\n')));
    saveRun();
}

QJsonObject VerifyModuleWizard::resultJson() const
{
    QJsonObject o = verify::toJson(m_report, tr("Verify module wizard"));
    // What the calibration history lists and its report shows.
    o.insert(QStringLiteral("reason"), m_report.reasons.isEmpty() ? QString() : m_report.reasons.front());
    const QJsonObject att = o.value(QStringLiteral("attitude_error_deg")).toObject();
    o.insert(QStringLiteral("roll_error_deg"), att.value(QStringLiteral("roll")));
    o.insert(QStringLiteral("pitch_error_deg"), att.value(QStringLiteral("pitch")));
    o.insert(QStringLiteral("heading_error_deg"), att.value(QStringLiteral("heading")));
    o.remove(QStringLiteral("pose_list"));
    o.remove(QStringLiteral("attitude_error_deg"));
    o.remove(QStringLiteral("dynamic"));
    o.remove(QStringLiteral("reasons"));
    return o;
}

void VerifyModuleWizard::saveRun()
{
    m_saver.save(QStringLiteral("verify"), resultJson(), m_rows);
    m_saved->setText(m_saver.statusText());
    m_pdf->setEnabled(m_saver.saved());
}

void VerifyModuleWizard::exportPdf()
{
    const QString path = QFileDialog::getSaveFileName(this, tr("Export report"), QStringLiteral("verify-report.pdf"),
                                                      tr("PDF (*.pdf)"));
    if (path.isEmpty())
        return;
    calib::CalibrationRecord record;
    record.kind = QStringLiteral("verify");
    record.time = QDateTime::currentDateTimeUtc();
    record.deviceSerial = m_saver.serial();
    record.result = resultJson();
    record.sampleCount = int(m_rows.rows.size());
    CalibrationReport report(record, m_rows);
    QString error;
    m_saved->setText(report.writePdf(path, &error) ? tr("Report written to %1").arg(path) : error);
}

} // namespace imudesk::ui
