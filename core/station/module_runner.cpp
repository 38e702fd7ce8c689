#include "core/station/module_runner.h"

#include "calib/gyro_scale_run.h"
#include "calib/mag_cal_session.h"
#include "device/device_session.h"
#include "core/firmware/firmware_updater.h"
#include "io/transport.h"
#include "model/sample.h"
#include "protocol/ihex/intel_hex_loader.h"
#include "calib/motion_check.h"
#include "record/allan_deviation.h"
#include "settings/config_profile.h"
#include "settings/configuration_controller.h"
#include "record/recording.h"

#include <QDir>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace imudesk::station {

using device::SessionState;

namespace {
QString number(double v)
{
    return QString::number(v, 'g', 4);
}
QString upTo(double limit)
{
    return QStringLiteral("≤ %1").arg(number(limit));
}
// Wraps an angle difference to (-180, 180].
double wrapDeg(double d)
{
    d = std::fmod(d + 180.0, 360.0);
    if (d <= 0)
        d += 360.0;
    return d - 180.0;
}
std::optional<model::FirmwareVersion> version(const QString &text)
{
    if (text.trimmed().isEmpty())
        return std::nullopt;
    return model::FirmwareVersion::parse(text.trimmed().toStdString());
}
QString versionText(const std::optional<model::FirmwareVersion> &v)
{
    return v ? QString::fromStdString(v->toString()) : QString();
}
} // namespace

ModuleRunner::ModuleRunner(TestPlan plan, QString port, Options options, QObject *parent)
    : QObject(parent), m_plan(std::move(plan)), m_port(std::move(port)), m_options(std::move(options))
{
    m_result = ModuleResult::pending(m_port, m_plan);
    m_pollTimer.setInterval(kPollMs);
    connect(&m_pollTimer, &QTimer::timeout, this, &ModuleRunner::poll);
    m_deadline.setSingleShot(true);
}

ModuleRunner::~ModuleRunner()
{
    m_magCal.reset();
    m_controller.reset();
    m_session.reset();
    if (m_updater) {
        m_updater->disconnect(this);
        m_updater->cancel();
    }
}

void ModuleRunner::start()
{
    if (m_running)
        return;
    m_running = true;
    m_result.started = QDateTime::currentDateTimeUtc();
    m_result.verdict = Verdict::Running;
    m_pollTimer.start();
    m_deadline.disconnect();
    connect(&m_deadline, &QTimer::timeout, this, [this] {
        fail(tr("the module did not answer on %1 within %2 s: check the cable, the power and the port")
                 .arg(m_port)
                 .arg(kConnectTimeoutMs / 1000));
    });
    m_deadline.start(kConnectTimeoutMs);
    openSession();
    Q_EMIT changed();
}

void ModuleRunner::openSession()
{
    m_connected = false;
    m_closingOnPurpose = false;
    m_session = std::make_unique<device::DeviceSession>(
        nullptr, m_options.transport ? m_options.transport(m_port) : std::unique_ptr<io::Transport>());
    m_session->setAutoReconnect(false); // a module that goes away fails; the others go on
    m_controller = std::make_unique<settings::ConfigurationController>(*m_session);
    connect(m_session.get(), &device::DeviceLink::stateChanged, this,
            [this](SessionState s, const QString &detail) {
                if (s == SessionState::Connected && !m_connected) {
                    m_connected = true;
                    onConnected();
                } else if ((s == SessionState::Disconnected || s == SessionState::Failed
                            || s == SessionState::Reconnecting)
                           && !m_closingOnPurpose) {
                    onLinkLost(detail.isEmpty() ? QString::fromLatin1(device::stateName(s)) : detail);
                }
            });
    connect(m_session.get(), &device::DeviceLink::statsUpdated, this, [this](const device::SessionStats &st) {
        m_frames = st.frames;
        m_framesLost = m_framesLostAtStart + st.framesLost;
        if (st.baud > 0)
            m_workingBaud = st.baud;
    });
    connect(m_controller.get(), &settings::ConfigurationController::readFinished, this,
            [this](bool ok, const QString &error) {
                if (!m_running || !m_readingIdentity)
                    return;
                m_readingIdentity = false;
                if (!ok) {
                    fail(tr("the module's settings could not be read: %1").arg(error));
                    return;
                }
                const auto &id = m_controller->identity();
                m_result.serialRaw = QByteArray::fromStdString(id.serial);
                m_result.serial = bytesAsText(m_result.serialRaw);
                m_result.product = QString::fromStdString(id.productName);
                const QString fw = versionText(id.firmware);
                if (m_index < 0) {
                    m_result.firmware = fw;
                    m_deadline.stop();
                    Q_EMIT changed();
                    runStep();
                    return;
                }
                // Back after the firmware update.
                m_result.firmwareAfter = fw;
                const auto min = version(planStep().text("minimum"));
                if (id.firmware && min && *id.firmware >= *min)
                    endStep(Verdict::Pass, tr("updated from %1 to %2 and verified").arg(m_result.firmware, fw));
                else
                    endStep(Verdict::Fail, tr("after the update the module reports firmware %1, older than %2")
                                               .arg(fw.isEmpty() ? tr("(none)") : fw, planStep().text("minimum")));
            });
    m_session->open(m_port, m_workingBaud > 0 ? m_workingBaud : m_options.baud);
}

void ModuleRunner::onConnected()
{
    m_lastData.restart();
    m_readingIdentity = true;
    m_controller->readAll();
}

void ModuleRunner::onLinkLost(const QString &detail)
{
    if (!m_running)
        return;
    m_result.end = ModuleResult::End::EquipmentFailed;
    if (m_index < 0)
        fail(tr("could not connect to %1: %2").arg(m_port, detail));
    else
        fail(tr("the module disappeared during \"%1\" (%2): check its cable; the other modules go on")
                 .arg(step().title, detail));
}

double ModuleRunner::stepWeight(const PlanStep &s) const
{
    if (!s.enabled)
        return 0.1;
    switch (s.kind) {
    case StepKind::Static:
    case StepKind::Allan:
    case StepKind::Attitude:
    case StepKind::Verify:
    case StepKind::Evidence: return std::max(1.0, s.number("seconds"));
    case StepKind::MagCal: return 40;
    case StepKind::GyroScale: return 60;
    case StepKind::Firmware: return 10;
    default: return 1;
    }
}

void ModuleRunner::updateProgress(double fraction)
{
    double total = 0, done = 0;
    for (size_t i = 0; i < m_plan.steps.size(); ++i) {
        const double w = stepWeight(m_plan.steps[i]);
        total += w;
        if (int(i) < m_index)
            done += w;
        else if (int(i) == m_index)
            done += w * std::clamp(fraction, 0.0, 1.0);
    }
    m_result.progress = total > 0 ? done / total : 1.0;
    Q_EMIT changed();
}

void ModuleRunner::runStep()
{
    if (!m_running)
        return;
    ++m_index;
    if (m_index >= int(m_plan.steps.size())) {
        finish();
        return;
    }
    m_result.currentStep = m_index;
    StepResult &r = step();
    r.started = QDateTime::currentDateTimeUtc();
    r.verdict = Verdict::Running;
    m_stepClock.restart();
    m_stepSeconds = stepWeight(planStep());
    updateProgress(0);
    const PlanStep &s = planStep();
    if (!s.enabled) {
        endStep(Verdict::Skipped, disabledDetail());
        return;
    }
    m_deadline.disconnect();
    switch (s.kind) {
    case StepKind::Identify: runIdentify(); break;
    case StepKind::Firmware: runFirmware(); break;
    case StepKind::Profile: runProfile(); break;
    case StepKind::Static:
    case StepKind::Allan:
    case StepKind::Attitude:
    case StepKind::Verify: startCollecting(s.number("seconds")); break;
    case StepKind::MagCal: runMagCal(); break;
    case StepKind::GyroScale: runGyroScale(); break;
    case StepKind::Save: runSave(); break;
    case StepKind::Evidence: runEvidence(); break;
    }
}

void ModuleRunner::endStep(Verdict verdict, const QString &detail)
{
    if (m_index < 0 || m_index >= int(m_result.steps.size()) || step().verdict != Verdict::Running)
        return;
    m_deadline.stop();
    m_collecting = false;
    StepResult &r = step();
    r.verdict = verdict;
    if (!detail.isEmpty())
        r.detail = detail;
    // A pass with values in a marginal band says which: the tiles and reports show the detail.
    QStringList marginal;
    for (const Measurement &m : r.values)
        if (m.marginal)
            marginal << m.name;
    if (verdict == Verdict::Pass && !marginal.isEmpty())
        r.detail = tr("%1; marginal: %2").arg(r.detail, marginal.join(QStringLiteral(", ")));
    r.finished = QDateTime::currentDateTimeUtc();
    if (verdict == Verdict::Fail) {
        // The steps after it are not run; one the plan turns off would not have run anyway,
        // and the report says so rather than blame the failure.
        for (size_t i = size_t(m_index) + 1; i < m_result.steps.size(); ++i) {
            m_result.steps[i].verdict = Verdict::Skipped;
            m_result.steps[i].detail =
                m_plan.steps[i].enabled ? tr("not run: \"%1\" failed").arg(r.title) : disabledDetail();
        }
        finish();
        return;
    }
    updateProgress(1);
    QTimer::singleShot(0, this, &ModuleRunner::runStep);
}

void ModuleRunner::fail(const QString &detail)
{
    if (!m_running)
        return;
    if (m_index < 0) {
        // Not connected: the failure goes to the first step the plan runs (a disabled step
        // stays "disabled in the plan").
        const auto first = std::find_if(m_plan.steps.begin(), m_plan.steps.end(),
                                        [](const PlanStep &s) { return s.enabled; });
        m_index = first == m_plan.steps.end() ? 0 : int(first - m_plan.steps.begin());
        for (int i = 0; i < m_index; ++i) {
            m_result.steps[size_t(i)].verdict = Verdict::Skipped;
            m_result.steps[size_t(i)].detail = disabledDetail();
        }
        m_result.currentStep = m_index;
        step().started = QDateTime::currentDateTimeUtc();
        step().verdict = Verdict::Running;
    }
    if (m_magCal)
        m_magCal->cancel();
    if (m_updater)
        m_updater->cancel();
    endStep(Verdict::Fail, detail);
}

QString ModuleRunner::disabledDetail()
{
    return tr("disabled in the plan");
}

void ModuleRunner::cancel()
{
    if (m_running)
        m_result.end = ModuleResult::End::Cancelled;
    fail(tr("cancelled by the operator"));
}

void ModuleRunner::finish()
{
    if (!m_running)
        return;
    m_running = false;
    m_pollTimer.stop();
    m_deadline.stop();
    m_collecting = false;
    m_gyroScale.reset();
    m_result.verdict = m_result.failedStep() >= 0 ? Verdict::Fail : Verdict::Pass;
    m_result.finished = QDateTime::currentDateTimeUtc();
    m_result.currentStep = -1;
    m_result.progress = 1;
    if (m_session) {
        m_closingOnPurpose = true;
        m_session->close(); // the port is free for the workspace or a re-run
    }
    Q_EMIT changed();
    Q_EMIT finished();
}

Measurement ModuleRunner::limited(const QString &name, double value, const QString &unit, const char *limitKey,
                                 bool magnitude) const
{
    const PlanStep &s = planStep();
    const double limit = s.number(limitKey);
    const auto band = s.marginalOf(limitKey);
    const double x = magnitude ? std::abs(value) : value;
    QString text = magnitude ? QStringLiteral("|x| ≤ %1").arg(number(limit)) : upTo(limit);
    if (band)
        text = tr("%1 (marginal > %2)").arg(text, number(*band));
    Measurement m{name, value, unit, text, x <= limit,
                  magnitude ? QStringLiteral("ABS_LE") : QStringLiteral("LE"), limit};
    m.marginalHigh = band;
    m.marginal = m.ok && band && x > *band;
    return m;
}

bool ModuleRunner::measure(const QString &name, double value, const QString &unit, const char *limitKey)
{
    step().values.push_back(limited(name, value, unit, limitKey, false));
    return step().values.back().ok;
}

bool ModuleRunner::measureMagnitude(const QString &name, double value, const QString &unit, const char *limitKey)
{
    step().values.push_back(limited(name, value, unit, limitKey, true));
    return step().values.back().ok;
}

void ModuleRunner::info(const QString &name, double value, const QString &unit)
{
    step().values.push_back(Measurement{name, value, unit, QString(), true});
}

// ---------------------------------------------------------------- identify

void ModuleRunner::runIdentify()
{
    const PlanStep &s = planStep();
    const auto &id = m_controller->identity();
    const QString product = QString::fromStdString(id.productName);
    QStringList wanted;
    for (const QString &p : s.text("products").split(QLatin1Char(','), Qt::SkipEmptyParts))
        wanted << p.trimmed();
    const bool productOk = wanted.isEmpty()
        || std::any_of(wanted.begin(), wanted.end(),
                       [&](const QString &p) { return product.startsWith(p, Qt::CaseInsensitive); });
    const auto min = version(s.text("firmware_min")), max = version(s.text("firmware_max"));
    const QString found = tr("%1, firmware %2, serial %3")
                              .arg(product.isEmpty() ? tr("(no product name)") : product,
                                   m_result.firmware.isEmpty() ? tr("(none)") : m_result.firmware,
                                   m_result.serial.isEmpty() ? tr("(none)") : m_result.serial);
    if (!productOk) {
        endStep(Verdict::Fail, tr("%1: not one of %2").arg(found, wanted.join(QStringLiteral(", "))));
        return;
    }
    if (!id.firmware || (min && *id.firmware < *min) || (max && *id.firmware > *max)) {
        endStep(Verdict::Fail, tr("%1: firmware outside %2 … %3")
                                   .arg(found, versionText(min).isEmpty() ? tr("any") : versionText(min),
                                        versionText(max).isEmpty() ? tr("any") : versionText(max)));
        return;
    }
    endStep(Verdict::Pass, found);
}

// ---------------------------------------------------------------- firmware

void ModuleRunner::runFirmware()
{
    const PlanStep &s = planStep();
    const auto min = version(s.text("minimum"));
    const auto &cur = m_controller->identity().firmware;
    if (!min) {
        endStep(Verdict::Fail, tr("the plan's minimum firmware \"%1\" is not a version").arg(s.text("minimum")));
        return;
    }
    if (cur && *cur >= *min) {
        endStep(Verdict::Pass, tr("firmware %1 is at least %2: no update needed").arg(versionText(cur), versionText(min)));
        return;
    }
    const QString imagePath = m_plan.resolve(s.text("image"));
    if (imagePath.isEmpty()) {
        endStep(Verdict::Fail, tr("firmware %1 is older than %2 and the plan names no image to update from")
                                   .arg(versionText(cur), versionText(min)));
        return;
    }
    auto loaded = protocol::ihex::IntelHexLoader::loadFile(imagePath);
    if (!loaded.ok()) {
        endStep(Verdict::Fail, tr("%1: %2 (nothing was sent to the module)")
                                   .arg(QDir::toNativeSeparators(imagePath), loaded.error));
        return;
    }
    if (const QString why = firmware::UpdateFlow::checkImage(*loaded.image, std::nullopt); !why.isEmpty()) {
        endStep(Verdict::Fail, tr("%1: %2 (nothing was sent to the module)").arg(QDir::toNativeSeparators(imagePath), why));
        return;
    }
    step().detail = tr("updating from %1 …").arg(versionText(cur));
    // The updater opens the port itself: the session goes first (its destructor closes the port).
    m_framesLostAtStart = m_framesLost;
    m_closingOnPurpose = true;
    m_controller.reset();
    m_session.reset();
    m_updater = std::make_unique<firmware::FirmwareUpdater>();
    connect(m_updater.get(), &firmware::UpdateRunner::progressChanged, this,
            [this](qulonglong done, qulonglong total, double, double) {
                if (total > 0)
                    updateProgress(0.9 * double(done) / double(total));
            });
    connect(m_updater.get(), &firmware::UpdateRunner::finished, this, [this](bool ok, const QString &message) {
        if (!m_running)
            return;
        const auto result = m_updater->result();
        m_updater.release()->deleteLater(); // not from inside its own signal
        if (!ok) {
            fail(tr("the update failed: %1").arg(message));
            return;
        }
        info(QStringLiteral("write_seconds"), result.writeSeconds, QStringLiteral("s"));
        info(QStringLiteral("bytes_written"), double(result.bytesWritten), QStringLiteral("B"));
        // Open the session again and read the version the module now reports (readFinished).
        m_deadline.disconnect();
        connect(&m_deadline, &QTimer::timeout, this,
                [this] { fail(tr("the module did not come back after the update within %1 s").arg(kConnectTimeoutMs / 1000)); });
        m_deadline.start(kConnectTimeoutMs);
        openSession();
    });
    firmware::UpdateFlow::Options o;
    o.baud = m_workingBaud > 0 ? m_workingBaud : 115200;
    if (!m_updater->start(m_port, *loaded.image, o))
        fail(tr("the updater could not start"));
}

// ---------------------------------------------------------------- profile, save

void ModuleRunner::runProfile()
{
    QString error;
    const QString path = m_plan.resolve(planStep().text("profile"));
    const auto profile = settings::ConfigProfile::load(path, &error);
    if (!profile) {
        endStep(Verdict::Fail, tr("profile %1: %2").arg(QDir::toNativeSeparators(path), error));
        return;
    }
    const auto &cfg = m_controller->configuration();
    QStringList notApplicable;
    for (const auto &d : profile->diff(cfg))
        if (!d.applicable)
            notApplicable << tr("%1=%2 (%3)").arg(d.key, d.profileValue, d.note);
    if (!notApplicable.isEmpty()) {
        endStep(Verdict::Fail, tr("the module cannot take: %1").arg(notApplicable.join(QStringLiteral("; "))));
        return;
    }
    const auto changes = profile->changesFor(cfg);
    if (changes.empty()) {
        info(QStringLiteral("settings_changed"), 0, QString());
        endStep(Verdict::Pass, tr("the module already holds every setting of the profile"));
        return;
    }
    auto c = std::make_shared<QMetaObject::Connection>();
    *c = connect(m_controller.get(), &settings::ConfigurationController::applyFinished, this,
                 [this, c](const settings::ConfigurationController::ApplyReport &report) {
                     disconnect(*c);
                     int verified = 0;
                     QStringList bad;
                     for (const auto &r : report.results) {
                         if (r.outcome == settings::ConfigurationController::Outcome::Verified)
                             ++verified;
                         else
                             bad << tr("%1=%2: %3 %4")
                                        .arg(r.key, r.requested,
                                             settings::ConfigurationController::outcomeName(r.outcome), r.detail)
                                        .trimmed();
                     }
                     info(QStringLiteral("settings_verified"), verified, QString());
                     step().values.push_back(Measurement{QStringLiteral("settings_failed"), double(bad.size()),
                                                         QString(), QStringLiteral("= 0"), bad.isEmpty()});
                     if (!report.error.isEmpty())
                         bad << report.error;
                     if (report.ok && bad.isEmpty())
                         endStep(Verdict::Pass, tr("%n setting(s) applied and read back", nullptr, verified));
                     else
                         endStep(Verdict::Fail, bad.join(QStringLiteral("; ")));
                 });
    m_controller->apply(changes);
}

void ModuleRunner::runSave()
{
    auto c = std::make_shared<QMetaObject::Connection>();
    *c = connect(m_controller.get(), &settings::ConfigurationController::actionFinished, this,
                 [this, c](const QString &, bool ok, const QString &detail) {
                     disconnect(*c);
                     if (ok)
                         endStep(Verdict::Pass, tr("SAVECONFIG answered OK"));
                     else
                         endStep(Verdict::Fail, tr("SAVECONFIG failed: %1").arg(detail));
                 });
    m_controller->save();
}

// ---------------------------------------------------------------- measurements at rest

void ModuleRunner::startCollecting(double seconds)
{
    m_samples.clear();
    m_nextSeq = m_session->store().totalAppended();
    m_collecting = true;
    m_stepSeconds = seconds;
    m_stepClock.restart();
    m_lastData.restart();
}

void ModuleRunner::poll()
{
    if (!m_session || !m_connected)
        return;
    uint64_t next = m_nextSeq;
    auto batch = m_session->store().since(m_nextSeq, SIZE_MAX, &next);
    m_nextSeq = next;
    if (!batch.empty())
        m_lastData.restart();
    for (auto &smp : batch) {
        if (!smp.has(model::FieldGyr) || !smp.has(model::FieldAcc))
            continue;
        if (m_source.empty())
            m_source = smp.source;
        if (smp.source != m_source)
            continue;
        if (m_gyroScale) {
            m_gyroScale->addSample(smp.deviceTimeMs, Eigen::Vector3d(smp.gyr.x, smp.gyr.y, smp.gyr.z),
                                   Eigen::Vector3d(smp.acc.x, smp.acc.y, smp.acc.z));
        }
        if (m_collecting && m_samples.size() < kMaxSamples)
            m_samples.push_back(std::move(smp));
    }
    const bool waitsForData = m_collecting || m_gyroScale;
    if (waitsForData && m_lastData.elapsed() > kSilenceMs) {
        m_result.end = ModuleResult::End::EquipmentFailed; // silent: the link or the module, not a measurement
        fail(tr("no data from the module for %1 s during \"%2\": is its output on, is it still connected?")
                 .arg(kSilenceMs / 1000)
                 .arg(step().title));
        return;
    }
    if (m_gyroScale) {
        const double elapsed = m_stepClock.elapsed() / 1000.0;
        updateProgress(std::min(0.95, elapsed / std::max(1.0, m_stepSeconds)));
        if (m_gyroScale->state() == calib::GyroScaleRun::State::Finished) {
            const auto r = m_gyroScale->result();
            m_gyroScale.reset();
            Measurement m = limited(QStringLiteral("scale_error"), r.scaleErrorPct, QStringLiteral("%"),
                                    "max_error_pct", true);
            // An incomplete or unacceptable run fails whatever its error: not marginal then.
            m.ok = m.ok && r.complete && r.acceptable;
            m.marginal = m.marginal && m.ok;
            const bool ok = m.ok;
            step().values.push_back(m);
            info(QStringLiteral("bias"), r.biasDps, QStringLiteral("°/s"));
            endStep(ok ? Verdict::Pass : Verdict::Fail, r.summary);
        }
        return;
    }
    if (!m_collecting) {
        if (m_index >= 0 && planStep().kind == StepKind::Evidence && step().verdict == Verdict::Running)
            updateProgress(std::min(0.99, m_stepClock.elapsed() / 1000.0 / m_stepSeconds));
        return;
    }
    // Done when the samples cover the step's time on the device's own clock, not the host's: on
    // a loaded machine the bytes of a second may arrive late. A module that sends nothing is
    // caught by the silence check above, one that sends too little by the time limit here.
    const double span = collectedSeconds();
    updateProgress(span / m_stepSeconds);
    const bool covered = span >= m_stepSeconds * 0.999;
    if (!covered && m_stepClock.elapsed() < qint64(m_stepSeconds * 1000) + kSilenceMs)
        return;
    m_collecting = false;
    if (m_samples.size() < 10) {
        fail(tr("only %1 samples in %2 s: enable the module's output (HI91, at least 10 Hz)")
                 .arg(m_samples.size())
                 .arg(m_stepSeconds));
        return;
    }
    switch (planStep().kind) {
    case StepKind::Static: evaluateStatic(); break;
    case StepKind::Allan: evaluateAllan(); break;
    case StepKind::Attitude: evaluateAttitude(); break;
    case StepKind::Verify: evaluateVerify(); break; // module_runner_verify.cpp
    default: break;
    }
}

double ModuleRunner::collectedSeconds() const
{
    const size_t n = m_samples.size();
    if (n < 2)
        return 0;
    // n samples span n intervals: (last - first) covers n - 1 of them.
    double span = (m_samples.back().deviceTimeMs - m_samples.front().deviceTimeMs) / 1000.0;
    if (span <= 0) // no device clock: the host's arrival times
        span = double(m_samples.back().hostTimeNs - m_samples.front().hostTimeNs) / 1e9;
    return std::max(0.0, span * double(n) / double(n - 1));
}

bool ModuleRunner::judgeableStill()
{
    calib::MotionCheck motion;
    for (const auto &x : m_samples)
        motion.add(x.has(model::FieldDeviceTime) ? x.deviceTimeMs / 1000.0 : double(x.hostTimeNs) / 1e9,
                   Eigen::Vector3d(x.gyr.x, x.gyr.y, x.gyr.z), Eigen::Vector3d(x.acc.x, x.acc.y, x.acc.z));
    const calib::MotionCheck::Result r = motion.result();
    if (!r.moved)
        return true;
    // Its noise, bias and Allan deviation would be the motion's: no number is judged, and the
    // module is not counted against the product (its record is ERROR).
    info(QStringLiteral("motion_gyro_std"), r.gyroStdDps, QStringLiteral("°/s"));
    m_result.end = ModuleResult::End::NotJudged;
    fail(tr("cannot judge: %1 (%2). Keep the module still on the fixture and test it again.").arg(r.reason(), r.detail()));
    return false;
}

void ModuleRunner::evaluateStatic()
{
    if (!judgeableStill())
        return;
    const size_t n = m_samples.size();
    auto stats = [&](auto get, double &mean, double &sd) {
        double sum = 0, sum2 = 0;
        for (const auto &x : m_samples)
            sum += get(x);
        mean = sum / double(n);
        for (const auto &x : m_samples)
            sum2 += (get(x) - mean) * (get(x) - mean);
        sd = std::sqrt(sum2 / double(n > 1 ? n - 1 : 1));
    };
    const char *axes[] = {"x", "y", "z"};
    Eigen::Vector3d accMean;
    bool ok = true;
    for (int a = 0; a < 3; ++a) {
        double mean = 0, sd = 0;
        stats([a](const model::Sample &x) { return a == 0 ? x.gyr.x : a == 1 ? x.gyr.y : x.gyr.z; }, mean, sd);
        ok &= measure(QStringLiteral("gyro_std_%1").arg(QLatin1String(axes[a])), sd, QStringLiteral("°/s"),
                      "gyro_std_max_dps");
        ok &= measureMagnitude(QStringLiteral("gyro_bias_%1").arg(QLatin1String(axes[a])), mean, QStringLiteral("°/s"),
                               "gyro_bias_max_dps");
    }
    for (int a = 0; a < 3; ++a) {
        double mean = 0, sd = 0;
        stats([a](const model::Sample &x) { return a == 0 ? x.acc.x : a == 1 ? x.acc.y : x.acc.z; }, mean, sd);
        accMean[a] = mean;
        ok &= measure(QStringLiteral("acc_std_%1").arg(QLatin1String(axes[a])), sd * 1000, QStringLiteral("mG"),
                      "acc_std_max_mg");
    }
    const double gErr = (accMean.norm() - 1.0) * 1000.0;
    ok &= measureMagnitude(QStringLiteral("gravity_error"), gErr, QStringLiteral("mG"), "gravity_tol_mg");
    info(QStringLiteral("samples"), double(n), QString());
    endStep(ok ? Verdict::Pass : Verdict::Fail,
            ok ? tr("%1 samples within every limit").arg(n) : tr("%1 samples; values outside the limits are marked").arg(n));
}

void ModuleRunner::evaluateAllan()
{
    if (!judgeableStill())
        return;
    const PlanStep &s = planStep();
    const double tau = s.number("tau_s");
    // The sample interval from the device's own clock (the host's arrival times jitter).
    const double spanMs = m_samples.back().deviceTimeMs - m_samples.front().deviceTimeMs;
    const double tau0 = spanMs > 0 ? spanMs / 1000.0 / double(m_samples.size() - 1)
                                   : m_stepSeconds / double(m_samples.size());
    info(QStringLiteral("sample_interval"), tau0 * 1000, QStringLiteral("ms"));
    const char *axes[] = {"x", "y", "z"};
    bool ok = true;
    std::vector<float> data(m_samples.size());
    for (int a = 0; a < 3; ++a) {
        for (size_t i = 0; i < m_samples.size(); ++i) {
            const auto &g = m_samples[i].gyr;
            data[i] = float(a == 0 ? g.x : a == 1 ? g.y : g.z);
        }
        const auto curve = record::AllanDeviation::compute(data.data(), data.size(), tau0);
        double sigma = 0;
        if (!record::AllanDeviation::at(curve, tau, &sigma)) {
            fail(tr("%1 s of data do not reach τ = %2 s: measure for at least %3 s")
                     .arg(m_stepSeconds)
                     .arg(tau)
                     .arg(std::ceil(tau * 10)));
            return;
        }
        ok &= measure(QStringLiteral("allan_%1").arg(QLatin1String(axes[a])), sigma, QStringLiteral("°/s"),
                      "sigma_max_dps");
    }
    endStep(ok ? Verdict::Pass : Verdict::Fail, tr("σ(%1 s) of each gyro axis").arg(tau));
}

void ModuleRunner::evaluateAttitude()
{
    const PlanStep &s = planStep();
    double sr = 0, cr = 0, sp = 0, cp = 0;
    size_t n = 0;
    for (const auto &x : m_samples) {
        if (!x.has(model::FieldEuler))
            continue;
        sr += std::sin(x.roll * model::kDegToRad);
        cr += std::cos(x.roll * model::kDegToRad);
        sp += std::sin(x.pitch * model::kDegToRad);
        cp += std::cos(x.pitch * model::kDegToRad);
        ++n;
    }
    if (n == 0) {
        fail(tr("the module's output carries no Euler angles: enable HI91 in the profile"));
        return;
    }
    const double roll = std::atan2(sr, cr) * model::kRadToDeg, pitch = std::atan2(sp, cp) * model::kRadToDeg;
    const double dRoll = wrapDeg(roll - s.number("roll_deg")), dPitch = wrapDeg(pitch - s.number("pitch_deg"));
    info(QStringLiteral("roll"), roll, QStringLiteral("°"));
    info(QStringLiteral("pitch"), pitch, QStringLiteral("°"));
    const bool rollOk = measureMagnitude(QStringLiteral("roll_error"), dRoll, QStringLiteral("°"), "tolerance_deg");
    const bool pitchOk = measureMagnitude(QStringLiteral("pitch_error"), dPitch, QStringLiteral("°"), "tolerance_deg");
    const bool ok = rollOk && pitchOk;
    endStep(ok ? Verdict::Pass : Verdict::Fail,
            ok ? tr("mounted as expected") : tr("roll %1°, pitch %2°: the module is not mounted as the plan expects")
                                                 .arg(number(roll), number(pitch)));
}

// ---------------------------------------------------------------- calibration runs

void ModuleRunner::runMagCal()
{
    const auto &id = m_controller->identity();
    if (!id.firmware) {
        endStep(Verdict::Fail, tr("the module reported no firmware version, so the calibration commands are unknown"));
        return;
    }
    calib::MagCalProcedure::Options o;
    o.timeoutMs = int(planStep().number("timeout_s") * 1000);
    m_magCal = std::make_unique<calib::MagCalSession>(*m_session, o);
    connect(m_magCal.get(), &calib::MagCalSession::progressChanged, this,
            [this](int, int progress, const QString &message) {
                step().detail = message;
                updateProgress(progress / 100.0);
            });
    connect(m_magCal.get(), &calib::MagCalSession::finished, this, [this](bool ok, const QString &message) {
        m_magCal.release()->deleteLater();
        endStep(ok ? Verdict::Pass : Verdict::Fail, message);
    });
    connect(&m_deadline, &QTimer::timeout, this, [this] {
        fail(tr("the calibration did not end within %1 s").arg(planStep().number("timeout_s")));
    });
    m_deadline.start(int(planStep().number("timeout_s") * 1000) + 5000);
    m_magCal->start(calib::MagCalProcedure::flowFor(*id.firmware));
}

void ModuleRunner::runGyroScale()
{
    m_gyroScale = std::make_unique<calib::GyroScaleRun>();
    m_gyroScale->start();
    m_stepSeconds = planStep().number("timeout_s");
    m_lastData.restart();
    connect(&m_deadline, &QTimer::timeout, this, [this] {
        m_gyroScale.reset();
        fail(tr("the turns did not end within %1 s: is the module on the turntable?").arg(planStep().number("timeout_s")));
    });
    m_deadline.start(int(m_stepSeconds * 1000));
}

// ---------------------------------------------------------------- evidence

void ModuleRunner::runEvidence()
{
    if (m_options.evidencePath.isEmpty()) {
        endStep(Verdict::Skipped, tr("no run folder to record into"));
        return;
    }
    const double seconds = planStep().number("seconds");
    auto progress = std::make_shared<quint64>(0);
    auto conns = std::make_shared<std::vector<QMetaObject::Connection>>();
    auto done = [this, conns] {
        for (auto &c : *conns)
            disconnect(c);
    };
    conns->push_back(connect(m_session.get(), &device::Session::recordingProgress, this,
                             [progress](quint64, quint64 frames) { *progress = frames; }));
    conns->push_back(connect(m_session.get(), &device::Session::recordingStopped, this,
                             [this, done, progress](const QString &reason) {
                                 done();
                                 if (!reason.isEmpty()) {
                                     fail(tr("the recording stopped: %1").arg(reason));
                                     return;
                                 }
                                 m_result.evidencePath = m_options.evidencePath;
                                 info(QStringLiteral("frames"), double(*progress), QString());
                                 endStep(Verdict::Pass, QDir::toNativeSeparators(m_options.evidencePath));
                             }));
    connect(&m_deadline, &QTimer::timeout, this, [this] { m_session->stopRecording(); });
    m_stepSeconds = seconds; // poll() shows the progress
    record::startRecording(*m_session, m_options.evidencePath);
    m_deadline.start(int(seconds * 1000));
}

} // namespace imudesk::station
