#include "calibration/hec495_calibration_wizard.h"
#include "common/work_place_size.h"

#include "attitude/compass_pose_view.h"
#include "device/hec495_session.h"
#include "model/attitude.h"

#include <QButtonGroup>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QRadioButton>
#include <QVBoxLayout>
#include <QWizardPage>

#include <cmath>

namespace imudesk::ui {

using calib::CompassCalMethod;
using calib::CompassPoseTracker;
using device::Hec495Result;
namespace wl = protocol::witlink;

namespace {

// The compass's heading, clockwise from north 0..360 (a sample's yaw is the world frame's, ENU).
double headingOf(const model::Sample &s)
{
    return s.has(model::FieldHeading) ? s.headingDeg : model::wrap360(-s.yaw);
}

constexpr CompassCalMethod kMethods[] = {CompassCalMethod::Auto12, CompassCalMethod::Manual,
                                         CompassCalMethod::AutoAllOrientation, CompassCalMethod::Auto12SmallTilt,
                                         CompassCalMethod::Planar};

// Where each method suits and its limits (the manual's comparison table after the methods).
QString suitsOf(CompassCalMethod m)
{
    switch (m) {
    case CompassCalMethod::Auto12:
        return Hec495CalibrationWizard::tr("Suits: the compass and its mount can be turned to the poses of the table. "
                                           "Good results; in a complex magnetic environment slightly less accurate "
                                           "than all-orientation. Limit: pitch must exceed 45 deg and roll 30 deg. "
                                           "The manual recommends trying this method first.");
    case CompassCalMethod::Manual:
        return Hec495CalibrationWizard::tr("Suits: the pitch and roll range of use is known; collect most points in "
                                           "the poses used most. Best at the chosen points; badly chosen points can "
                                           "spoil the calibration.");
    case CompassCalMethod::AutoAllOrientation:
        return Hec495CalibrationWizard::tr("Suits: the compass and its mount can turn to every orientation and the "
                                           "magnetic environment is complex. The most accurate over all attitudes.");
    case CompassCalMethod::Auto12SmallTilt:
        return Hec495CalibrationWizard::tr("Suits: roll stays below 5 deg in use while pitch varies widely. Best "
                                           "when roll is below 5 deg. Limit: pitch must exceed 45 deg.");
    case CompassCalMethod::Planar:
        return Hec495CalibrationWizard::tr("Suits: the compass only turns in a plane, pitch and roll below 2 deg. "
                                           "Best when it is used level.");
    }
    return {};
}

wl::CalibrationMethod deviceMethod(CompassCalMethod m)
{
    return wl::CalibrationMethod(CompassPoseTracker::startCommandCode(m));
}

} // namespace

Hec495CalibrationWizard::Hec495CalibrationWizard(device::Hec495Session &session, QWidget *parent)
    : QWizard(parent),
      m_session(session),
      m_tracker(CompassCalMethod::Auto12, kHeadingToleranceDeg)
{
    setWindowTitle(tr("HEC495 compass calibration"));
    fitWorkPlace(this, QSize(1100, 780), parent);
    buildMethodPage();
    buildRunPage();
    buildResultPage();
    m_clock.setInterval(kRefreshMs);
    connect(&m_clock, &QTimer::timeout, this, &Hec495CalibrationWizard::refresh);
    connect(&m_session, &device::Hec495Session::commandFinished, this, &Hec495CalibrationWizard::onCommandFinished);
    connect(&m_session, &device::Hec495Session::calibrationPoint, this, &Hec495CalibrationWizard::onPoint);
    connect(this, &QWizard::currentIdChanged, this, &Hec495CalibrationWizard::onPageChanged);
}

Hec495CalibrationWizard::~Hec495CalibrationWizard() = default;

void Hec495CalibrationWizard::buildMethodPage()
{
    auto *page = new QWizardPage;
    page->setTitle(tr("Choose the calibration method"));
    page->setSubTitle(tr("Calibrate in the place of use, with the compass fixed in its mount: everything near it "
                         "(iron, batteries, motors, cables with current) must turn together with it. Carry no "
                         "phone, keys or other metal while calibrating."));
    auto *layout = new QVBoxLayout(page);
    m_methods = new QButtonGroup(this);
    for (CompassCalMethod m : kMethods) {
        auto *b = new QRadioButton(tr("%1 (command 0x%2)")
                                       .arg(CompassPoseTracker::methodName(m))
                                       .arg(CompassPoseTracker::startCommandCode(m), 2, 16, QLatin1Char('0')));
        m_methods->addButton(b, int(m));
        layout->addWidget(b);
    }
    m_instructions = new QLabel;
    m_instructions->setWordWrap(true);
    m_instructions->setTextFormat(Qt::PlainText);
    layout->addWidget(m_instructions);
    layout->addStretch();
    setPage(MethodPage, page);
    connect(m_methods, &QButtonGroup::idClicked, this, [this](int id) { setMethod(CompassCalMethod(id)); });
    setMethod(CompassCalMethod::Auto12);
}

void Hec495CalibrationWizard::buildRunPage()
{
    auto *page = new QWizardPage;
    page->setTitle(tr("Calibrate"));
    auto *layout = new QHBoxLayout(page);
    m_view = new CompassPoseView;
    m_view->setTracker(&m_tracker);
    layout->addWidget(m_view, 3);

    auto *side = new QVBoxLayout;
    m_method = new QLabel;
    m_method->setWordWrap(true);
    side->addWidget(m_method);
    m_count = new QLabel;
    side->addWidget(m_count);
    m_progress = new QProgressBar;
    m_progress->setRange(0, 100);
    side->addWidget(m_progress);
    m_legend = new QLabel(tr("Targets: inner ring pitch up (above 45 deg), middle ring level, outer ring pitch "
                             "down (below -45 deg); R is the roll to hold. Green: collected; orange outline: the "
                             "target the compass is at. The red needle is the heading, the blue dot the pitch, the "
                             "bar below the roll."));
    m_legend->setWordWrap(true);
    side->addWidget(m_legend);
    m_hint = new QLabel;
    m_hint->setWordWrap(true);
    side->addWidget(m_hint);
    auto *buttons = new QGridLayout;
    m_start = new QPushButton(tr("Start calibration"));
    m_collect = new QPushButton(tr("Collect point"));
    m_stop = new QPushButton(tr("Stop"));
    m_save = new QPushButton(tr("Save calibration"));
    m_clearButton = new QPushButton(tr("Clear calibration"));
    m_start->setToolTip(tr("Sends the start command of the method (77 04 00 xx)."));
    m_collect->setToolTip(tr("Manual method: stores the current pose as a calibration point (0x67)."));
    m_stop->setToolTip(tr("Abandons the run without saving (0x12)."));
    m_save->setToolTip(tr("Computes and stores the calibration from the points collected (0x09)."));
    m_clearButton->setToolTip(tr("Erases the environment calibration stored in the module (0x10)."));
    buttons->addWidget(m_start, 0, 0);
    buttons->addWidget(m_collect, 0, 1);
    buttons->addWidget(m_stop, 1, 0);
    buttons->addWidget(m_save, 1, 1);
    buttons->addWidget(m_clearButton, 2, 0, 1, 2);
    side->addLayout(buttons);
    // An automatic method's question before 0x09 (the module chose its points itself).
    m_confirm = new QWidget;
    auto *confirmLayout = new QVBoxLayout(m_confirm);
    confirmLayout->setContentsMargins(0, 0, 0, 0);
    m_confirmText = new QLabel;
    m_confirmText->setWordWrap(true);
    confirmLayout->addWidget(m_confirmText);
    auto *confirmButtons = new QHBoxLayout;
    m_confirmSave = new QPushButton(tr("Save to the compass"));
    m_cancelSave = new QPushButton(tr("Not yet"));
    m_cancelSave->setToolTip(tr("Keeps the run going: turn the compass to more targets, or stop without saving."));
    confirmButtons->addWidget(m_confirmSave);
    confirmButtons->addWidget(m_cancelSave);
    confirmLayout->addLayout(confirmButtons);
    m_confirm->hide();
    side->addWidget(m_confirm);
    m_status = new QLabel;
    m_status->setWordWrap(true);
    side->addWidget(m_status);
    m_error = new QLabel;
    m_error->setWordWrap(true);
    m_error->setStyleSheet(QStringLiteral("color: #b00020;"));
    side->addWidget(m_error);
    side->addStretch();
    layout->addLayout(side, 2);
    setPage(RunPage, page);

    connect(m_start, &QPushButton::clicked, this, [this] {
        m_tracker.clear();
        m_fitErr.reset();
        m_savedPoints = 0;
        send(RunState::Starting, m_session.startCalibration(deviceMethod(method())));
    });
    connect(m_collect, &QPushButton::clicked, this,
            [this] { send(RunState::Collecting, m_session.collectCalibrationPoint()); });
    connect(m_stop, &QPushButton::clicked, this, [this] { send(RunState::Stopping, m_session.stopCalibration()); });
    connect(m_save, &QPushButton::clicked, this, [this] {
        if (method() == CompassCalMethod::Manual) { // every point was the operator's own choice
            send(RunState::Saving, m_session.saveCalibration());
            return;
        }
        const int max = CompassPoseTracker::maxPoints(method());
        m_confirmText->setText(
            tr("The module collected %1 points (at most %2) by itself. Saving computes the calibration from them and "
               "replaces the compass's current calibration; this cannot be undone. Save now?")
                .arg(m_tracker.validPoints())
                .arg(max));
        m_confirm->show();
        updateControls();
    });
    connect(m_confirmSave, &QPushButton::clicked, this, [this] {
        m_confirm->hide();
        send(RunState::Saving, m_session.saveCalibration());
    });
    connect(m_cancelSave, &QPushButton::clicked, this, [this] {
        m_confirm->hide();
        m_status->setText(tr("Not saved yet: the run goes on."));
        updateControls();
    });
    connect(m_clearButton, &QPushButton::clicked, this,
            [this] { send(RunState::Clearing, m_session.clearCalibration()); });
}

void Hec495CalibrationWizard::buildResultPage()
{
    auto *page = new QWizardPage;
    page->setTitle(tr("Result"));
    auto *layout = new QVBoxLayout(page);
    m_result = new QLabel;
    m_result->setWordWrap(true);
    layout->addWidget(m_result);
    m_again = new QPushButton(tr("Calibrate again"));
    layout->addWidget(m_again, 0, Qt::AlignLeft);
    layout->addStretch();
    setPage(ResultPage, page);
    page->setFinalPage(true);
    connect(m_again, &QPushButton::clicked, this, &Hec495CalibrationWizard::calibrateAgain);
}

void Hec495CalibrationWizard::setMethod(CompassCalMethod m)
{
    if (QAbstractButton *b = m_methods->button(int(m)))
        b->setChecked(true);
    if (m_running)
        return; // the run's method stays until it is stopped or saved
    m_tracker = CompassPoseTracker(m, kHeadingToleranceDeg);
    m_instructions->setText(CompassPoseTracker::instructions(m) + QStringLiteral("\n\n") + suitsOf(m)
                            + QStringLiteral("\n\n")
                            + tr("Then save: the module replies with its fit error (FitErr); the smaller the better, "
                                 "above %1 calibrate again.")
                                  .arg(CompassPoseTracker::kMaxGoodFitErr, 0, 'f', 0));
    if (m_view)
        m_view->update();
}

CompassCalMethod Hec495CalibrationWizard::method() const
{
    return m_tracker.method();
}

void Hec495CalibrationWizard::onPageChanged(int id)
{
    if (id == RunPage) {
        setMethod(CompassCalMethod(m_methods->checkedId()));
        page(RunPage)->setSubTitle(CompassPoseTracker::instructions(method()));
        m_method->setText(tr("Method: %1").arg(CompassPoseTracker::methodName(method())));
        m_legend->setVisible(!m_tracker.poseTargets().empty());
        m_clock.start();
        refresh();
        updateControls();
        updateCount();
        button(QWizard::NextButton)->setEnabled(saved());
    } else {
        m_clock.stop();
    }
    if (id == MethodPage && m_running && m_state != RunState::Stopping)
        send(RunState::Stopping, m_session.stopCalibration());
    if (id == ResultPage)
        m_result->setText(resultText());
}

void Hec495CalibrationWizard::refresh()
{
    if (m_running) {
        uint64_t next = m_seq;
        const auto samples = m_session.store().since(m_seq, SIZE_MAX, &next);
        m_seq = next;
        for (const auto &x : samples) {
            if (m_rows.rows.size() >= CalibrationRunSaver::kMaxRows || !(x.fields & model::FieldEuler))
                continue;
            const bool mag = x.fields & model::FieldMag;
            m_rows.rows.push_back({double(x.deviceTimeMs), headingOf(x), x.pitch, x.roll, mag ? x.mag.x : 0.0,
                                   mag ? x.mag.y : 0.0, mag ? x.mag.z : 0.0});
        }
    }
    const auto s = m_session.store().latest();
    if (!s || !(s->fields & model::FieldEuler)) {
        m_view->setPose(std::nullopt);
        return;
    }
    const double heading = headingOf(*s);
    m_tracker.updatePose(heading, s->pitch, s->roll);
    m_view->setPose(CompassPoseView::Pose{heading, s->pitch, s->roll});
    if (m_running)
        m_hint->setText(m_tracker.nextHint());
}

void Hec495CalibrationWizard::send(RunState state, quint64 id)
{
    m_state = state;
    m_pending = id;
    m_error->clear();
    switch (state) {
    case RunState::Starting: m_status->setText(tr("Starting the calibration...")); break;
    case RunState::Collecting: m_status->setText(tr("Collecting a point...")); break;
    case RunState::Stopping: m_status->setText(tr("Stopping the calibration...")); break;
    case RunState::Saving: m_status->setText(tr("Saving the calibration...")); break;
    case RunState::Clearing: m_status->setText(tr("Clearing the stored calibration...")); break;
    default: break;
    }
    updateControls();
}

void Hec495CalibrationWizard::onCommandFinished(quint64 id, const Hec495Result &result)
{
    if (id == 0 || id != m_pending)
        return;
    const RunState state = m_state;
    m_pending = 0;
    m_state = RunState::Idle;
    if (!result.ok()) {
        handleFailure(state, result);
    } else {
        switch (state) {
        case RunState::Starting:
            m_running = true;
            m_tracker.clear();
            m_seq = m_session.store().totalAppended();
            m_rows.columns = {QStringLiteral("time_ms"), QStringLiteral("heading"), QStringLiteral("pitch"),
                              QStringLiteral("roll"),    QStringLiteral("mag_x"),   QStringLiteral("mag_y"),
                              QStringLiteral("mag_z")};
            m_rows.rows.clear();
            refresh(); // the pose the first point is taken at
            m_status->setText(tr("Calibration running (%1). Turn the compass as shown; targets light up as the "
                                 "module collects points.")
                                  .arg(CompassPoseTracker::methodName(method())));
            m_hint->setText(m_tracker.nextHint());
            break;
        case RunState::Collecting:
            if (result.reply.kind == wl::Reply::Kind::CalibrationPoint)
                onPoint(result.reply.points);
            m_status->setText(tr("Point collected."));
            break;
        case RunState::Stopping:
            m_running = false;
            m_tracker.clear();
            m_status->setText(tr("Calibration stopped; nothing was saved. The module keeps its previous "
                                 "calibration."));
            break;
        case RunState::Clearing:
            m_running = false;
            m_tracker.clear();
            m_fitErr.reset();
            m_status->setText(tr("The stored environment calibration was cleared from the module. Start a new "
                                 "calibration before relying on the heading near iron."));
            break;
        case RunState::Saving:
            if (result.reply.kind == wl::Reply::Kind::CalibrationSaved) {
                m_running = false;
                m_fitErr = result.reply.fitError;
                m_savedPoints = result.reply.points;
                m_saver.save(QStringLiteral("compass"), resultJson(), m_rows);
                m_status->setText(tr("Calibration saved."));
            } else {
                setError(tr("The module answered the save command without a fit error (%1). Collect the points "
                            "again and save once more.")
                             .arg(result.reply.describe()));
            }
            break;
        default: break;
        }
    }
    updateControls();
    updateCount();
    Q_EMIT requestFinished(result);
    if (state == RunState::Saving && saved() && currentId() == RunPage) {
        button(QWizard::NextButton)->setEnabled(true);
        next();
    }
}

void Hec495CalibrationWizard::handleFailure(RunState state, const Hec495Result &result)
{
    QString todo;
    switch (result.status) {
    case Hec495Result::Status::Timeout:
        todo = tr("Check the cable, the power, the baud rate and the module address, then try again.");
        break;
    case Hec495Result::Status::NotSent:
    case Hec495Result::Status::Cancelled:
    case Hec495Result::Status::Pending: // (a failure has an outcome)
        todo = tr("The connection is closed: connect to the compass again, then restart the calibration.");
        break;
    case Hec495Result::Status::Invalid:
        todo = tr("The reply was not one the manual allows: check that the device is an HEC495 and try again.");
        break;
    case Hec495Result::Status::Refused:
    case Hec495Result::Status::Ok:
        switch (state) {
        case RunState::Saving:
            todo = tr("The module could not compute a calibration: too few points, or points that do not span the "
                      "field. Start the calibration again and turn through more of the target poses before saving.");
            break;
        case RunState::Collecting:
            todo = tr("The module did not take the point: no manual calibration is running, or it is full. Start "
                      "the manual method first.");
            break;
        case RunState::Starting:
            todo = tr("The module refused to start this method. Stop any calibration in progress and try again.");
            break;
        default: todo = tr("Try again; if it keeps failing, power the module off and on."); break;
        }
        break;
    }
    if (state == RunState::Starting || (state == RunState::Saving && result.status == Hec495Result::Status::Refused)
        || result.status == Hec495Result::Status::NotSent
        || result.status == Hec495Result::Status::Cancelled)
        m_running = false;
    m_status->clear();
    setError(tr("Failed: %1.\n%2").arg(result.message, todo));
}

void Hec495CalibrationWizard::onPoint(int count)
{
    m_tracker.setValidPoints(count);
    updateCount();
    if (m_running)
        m_hint->setText(m_tracker.nextHint());
    m_view->update();
}

void Hec495CalibrationWizard::updateCount()
{
    const int max = CompassPoseTracker::maxPoints(method());
    m_count->setText(max > 0 ? tr("Valid points: %1 of at most %2").arg(m_tracker.validPoints()).arg(max)
                             : tr("Valid points: %1 (at least %2)")
                                   .arg(m_tracker.validPoints())
                                   .arg(CompassPoseTracker::minPoints(method())));
    m_progress->setValue(int(std::lround(m_tracker.progressPct())));
}

void Hec495CalibrationWizard::updateControls()
{
    const bool idle = m_pending == 0;
    m_start->setEnabled(idle && !m_running);
    m_collect->setVisible(method() == CompassCalMethod::Manual);
    m_collect->setEnabled(idle && m_running && method() == CompassCalMethod::Manual);
    m_stop->setEnabled(idle && m_running);
    m_save->setEnabled(idle && m_running && m_confirm->isHidden());
    m_confirmSave->setEnabled(idle && m_running);
    if (!m_running) // stopped, failed or closed meanwhile: nothing left to confirm
        m_confirm->hide();
    m_clearButton->setEnabled(idle && !m_running);
}

void Hec495CalibrationWizard::setError(const QString &text)
{
    m_error->setText(text);
}

QString Hec495CalibrationWizard::statusText() const
{
    return m_status->text();
}

QString Hec495CalibrationWizard::errorText() const
{
    return m_error->text();
}

QString Hec495CalibrationWizard::resultText() const
{
    if (!m_fitErr)
        return tr("No calibration was saved.");
    const QString figures = tr("Fit error (FitErr): %1\nPoints used: %2\nMethod: %3")
                                .arg(double(*m_fitErr), 0, 'f', 2)
                                .arg(m_savedPoints)
                                .arg(CompassPoseTracker::methodName(method()));
    const QString verdict = redoRecommended()
        ? tr("FitErr is above %1: the manual says to calibrate again. Check that nothing magnetic moved relative "
             "to the compass during the run, that no phone or keys were near, and turn through the target poses "
             "more carefully; press \"Calibrate again\".")
              .arg(CompassPoseTracker::kMaxGoodFitErr, 0, 'f', 0)
        : tr("Good: FitErr is at most %1. The module stores and uses the calibration from now on.")
              .arg(CompassPoseTracker::kMaxGoodFitErr, 0, 'f', 0);
    return figures + QStringLiteral("\n\n") + verdict + QStringLiteral("\n\n") + m_saver.statusText();
}

QJsonObject Hec495CalibrationWizard::resultJson() const
{
    QJsonObject o;
    o.insert(QStringLiteral("method"), CompassPoseTracker::methodName(method()));
    o.insert(QStringLiteral("method_code"), int(CompassPoseTracker::startCommandCode(method())));
    if (m_fitErr)
        o.insert(QStringLiteral("fit_err"), double(*m_fitErr));
    o.insert(QStringLiteral("points"), m_savedPoints);
    o.insert(QStringLiteral("valid_points"), m_tracker.validPoints());
    o.insert(QStringLiteral("max_good_fit_err"), CompassPoseTracker::kMaxGoodFitErr);
    const bool good = m_fitErr && CompassPoseTracker::fitErrAcceptable(*m_fitErr);
    o.insert(QStringLiteral("verdict"), QLatin1String(good ? "pass" : "fail"));
    o.insert(QStringLiteral("reason"),
             good ? tr("FitErr %1 is at most %2.").arg(double(*m_fitErr), 0, 'f', 2).arg(CompassPoseTracker::kMaxGoodFitErr, 0, 'f', 0)
                  : tr("FitErr %1 is above %2: the manual says to calibrate again.")
                        .arg(m_fitErr ? double(*m_fitErr) : 0.0, 0, 'f', 2)
                        .arg(CompassPoseTracker::kMaxGoodFitErr, 0, 'f', 0));
    return o;
}

void Hec495CalibrationWizard::calibrateAgain()
{
    m_fitErr.reset();
    m_savedPoints = 0;
    m_tracker.clear();
    m_status->clear();
    m_error->clear();
    back();
}

bool Hec495CalibrationWizard::validateCurrentPage()
{
    if (currentId() == RunPage)
        return saved();
    return true;
}

void Hec495CalibrationWizard::done(int result)
{
    m_clock.stop();
    if ((m_running || m_state == RunState::Starting) && m_state != RunState::Stopping) {
        m_session.stopCalibration();
        m_running = false;
    }
    QWizard::done(result);
}

} // namespace imudesk::ui
