#include "sample_analyzer.h"

#include <algorithm>
#include <cmath>

namespace imudesk::record {

namespace {

struct ChannelDef {
    const char *name;
    const char *unit;
};
constexpr ChannelDef kDefs[] = {
    {"acc_x", "G"},      {"acc_y", "G"},      {"acc_z", "G"},    {"gyr_x", "deg/s"}, {"gyr_y", "deg/s"},
    {"gyr_z", "deg/s"},  {"mag_x", "uT"},     {"mag_y", "uT"},   {"mag_z", "uT"},    {"roll", "deg"},
    {"pitch", "deg"},    {"yaw", "deg"},      {"temperature", "degC"}, {"pressure", "Pa"},
};

} // namespace

void SampleAnalyzer::Running::add(double x)
{
    if (n == 0)
        min = max = x;
    ++n;
    const double d = x - mean;
    mean += d / double(n);
    m2 += d * (x - mean);
    min = std::min(min, x);
    max = std::max(max, x);
}

void SampleAnalyzer::add(const model::Sample &s)
{
    using namespace model;
    if (m_source.empty()) {
        if (!s.has(FieldGyr))
            return;
        m_source = s.source;
    }
    if (s.source != m_source)
        return;
    ++m_frames;
    const double values[kChannels] = {s.acc.x, s.acc.y, s.acc.z, s.gyr.x, s.gyr.y, s.gyr.z, s.mag.x,
                                      s.mag.y, s.mag.z, s.roll, s.pitch, s.yaw, s.temperatureC, s.pressurePa};
    const SampleField present[kChannels] = {FieldAcc, FieldAcc, FieldAcc, FieldGyr, FieldGyr, FieldGyr, FieldMag,
                                            FieldMag, FieldMag, FieldEuler, FieldEuler, FieldEuler,
                                            FieldTemperature, FieldPressure};
    for (size_t i = 0; i < kChannels; ++i)
        if (s.has(present[i]))
            m_stats[i].add(values[i]);
    if (s.has(FieldGyr) && s.has(FieldAcc)) {
        m_axes[0].push_back(float(s.gyr.x));
        m_axes[1].push_back(float(s.gyr.y));
        m_axes[2].push_back(float(s.gyr.z));
        m_axes[3].push_back(float(s.acc.x));
        m_axes[4].push_back(float(s.acc.y));
        m_axes[5].push_back(float(s.acc.z));
        const double timeS = s.has(FieldDeviceTime) ? s.deviceTimeMs / 1000.0 : double(s.hostTimeNs) / 1e9;
        m_motion.add(timeS, Eigen::Vector3d(s.gyr.x, s.gyr.y, s.gyr.z), Eigen::Vector3d(s.acc.x, s.acc.y, s.acc.z));
    }
    if (s.has(FieldDeviceTime)) {
        if (m_haveTime)
            m_intervals.push_back(float(s.deviceTimeMs - m_lastMs));
        else
            m_firstMs = s.deviceTimeMs;
        m_haveTime = true;
        m_lastMs = s.deviceTimeMs;
        m_gaps.add(s.source, s.deviceTimeMs);
    }
}

SampleAnalyzer::Result SampleAnalyzer::finish(double tauMax, int histogramBins) const
{
    Result r;
    r.source = m_source;
    r.frames = m_frames;
    for (size_t i = 0; i < kChannels; ++i) {
        const Running &s = m_stats[i];
        if (!s.n)
            continue;
        Channel c;
        c.name = kDefs[i].name;
        c.unit = kDefs[i].unit;
        c.count = s.n;
        c.mean = s.mean;
        c.std = s.n > 1 ? std::sqrt(s.m2 / double(s.n - 1)) : 0;
        c.min = s.min;
        c.max = s.max;
        r.channels.push_back(c);
    }
    r.framesLost = m_gaps.lost();
    r.deviceResets = m_gaps.resets();
    // Rate and jitter from the device clock (intervals across a reset are left out).
    std::vector<float> iv;
    iv.reserve(m_intervals.size());
    for (float d : m_intervals)
        if (d >= 0)
            iv.push_back(d);
    if (!iv.empty()) {
        double sum = 0, sum2 = 0;
        for (float d : iv) {
            sum += d;
            sum2 += double(d) * d;
        }
        const double n = double(iv.size());
        r.intervalMeanMs = sum / n;
        r.intervalStdMs = std::sqrt(std::max(0.0, sum2 / n - r.intervalMeanMs * r.intervalMeanMs));
        r.intervalMinMs = *std::min_element(iv.begin(), iv.end());
        r.intervalMaxMs = *std::max_element(iv.begin(), iv.end());
        r.durationS = sum / 1000.0;
        // The device's rate: frames lost on the link were output too.
        r.rateHz = sum > 0 ? (n + double(r.framesLost)) * 1000.0 / sum : 0;
        // Bins over [0, 2 x mean interval), the last one open-ended.
        const int bins = std::max(2, histogramBins);
        const double width = 2.0 * r.intervalMeanMs / (bins - 1);
        r.intervals.resize(size_t(bins));
        for (int b = 0; b < bins; ++b) {
            r.intervals[size_t(b)].fromMs = b * width;
            r.intervals[size_t(b)].toMs = b + 1 < bins ? (b + 1) * width : INFINITY;
        }
        for (float d : iv) {
            const int b = width > 0 ? std::min(bins - 1, int(d / width)) : 0;
            ++r.intervals[size_t(b)].count;
        }
    }
    // Allan deviation at the output period, of a module that stayed still, over a recording
    // long enough for the curve to reach the random walk's τ.
    r.motion = m_motion.result();
    r.tau0S = r.rateHz > 0 ? 1.0 / r.rateHz : 0;
    const size_t n = m_axes[0].size();
    const size_t longestCluster = n >= 3 ? (n - 1) / 2 : 0;
    if (r.motion.moved)
        r.allanWhyNot = AllanWhyNot::Moved;
    else if (r.tau0S <= 0 || double(longestCluster) * r.tau0S < kRandomWalkTauS * (1.0 - 1e-9))
        r.allanWhyNot = AllanWhyNot::TooShort;
    static const char *names[6] = {"gyr_x", "gyr_y", "gyr_z", "acc_x", "acc_y", "acc_z"};
    for (size_t a = 0; a < 6 && r.allanJudged(); ++a) {
        Axis axis;
        axis.name = names[a];
        axis.unit = a < 3 ? "deg/s" : "G";
        axis.curve = AllanDeviation::compute(m_axes[a].data(), m_axes[a].size(), r.tau0S);
        axis.summary = AllanDeviation::summarize(axis.curve);
        r.axes.push_back(std::move(axis));
    }
    r.tauMax = tauMax;
    r.recommendedLengthS = AllanDeviation::recommendedLength(tauMax);
    return r;
}

QString SampleAnalyzer::Result::allanReason() const
{
    switch (allanWhyNot) {
    case AllanWhyNot::Judged: return QString();
    case AllanWhyNot::Moved: return motion.reason();
    case AllanWhyNot::TooShort: return SampleAnalyzer::tr("cannot judge: the recording is too short");
    }
    return QString();
}

QString SampleAnalyzer::Result::allanDetail() const
{
    switch (allanWhyNot) {
    case AllanWhyNot::Judged: return QString();
    case AllanWhyNot::Moved: return motion.detail();
    case AllanWhyNot::TooShort:
        // The curve reaches τ = 1 s from 2 s of data; its uncertainty there is 10 % from the
        // recommended length.
        return SampleAnalyzer::tr("%1 frames over %2 s; the random walk is read at τ = %3 s, which needs at least %4 s "
                                  "of a still module (%5 s for 10 % uncertainty)")
            .arg(frames)
            .arg(durationS, 0, 'f', 2)
            .arg(kRandomWalkTauS, 0, 'g', 3)
            .arg(2.0 * kRandomWalkTauS, 0, 'g', 3)
            .arg(AllanDeviation::recommendedLength(kRandomWalkTauS), 0, 'f', 0);
    }
    return QString();
}

} // namespace imudesk::record
