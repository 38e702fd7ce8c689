<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en_US">
<context>
    <name>CanSurvey</name>
    <message numerus="yes">
        <location filename="../core/discovery/can_survey.cpp" line="+249"/>
        <source>%1 (and %n more time(s) like it)</source>
        <translation>
            <numerusform>%1 (and %n more time like it)</numerusform>
            <numerusform>%1 (and %n more times like it)</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>CaptureExporter</name>
    <message numerus="yes">
        <location filename="../core/record/capture_exporter.cpp" line="+540"/>
        <source>%n damaged chunk(s) were skipped</source>
        <translation>
            <numerusform>%n damaged chunk was skipped</numerusform>
            <numerusform>%n damaged chunks were skipped</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>CaptureSource</name>
    <message numerus="yes">
        <location filename="../core/record/capture_source.cpp" line="+122"/>
        <source>%1 is a vendor CSV: %n row(s) read, times from its pc_counter column</source>
        <translation>
            <numerusform>%1 is a vendor CSV: %n row read, times from its pc_counter column</numerusform>
            <numerusform>%1 is a vendor CSV: %n rows read, times from its pc_counter column</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+12"/>
        <source>The device clock restarted or jumped %n time(s); the times go on across each jump.</source>
        <translation>
            <numerusform>The device clock restarted or jumped %n time; the times go on across each jump.</numerusform>
            <numerusform>The device clock restarted or jumped %n times; the times go on across each jump.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>FileAnalysis</name>
    <message numerus="yes">
        <location filename="../core/record/file_analysis.cpp" line="+54"/>
        <source>%n damaged chunk(s) were skipped</source>
        <translation>
            <numerusform>%n damaged chunk was skipped</numerusform>
            <numerusform>%n damaged chunks were skipped</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>imudesk::models::LatestValuesModel</name>
    <message numerus="yes">
        <location filename="../core/itemmodels/latest_values_model.cpp" line="+149"/>
        <source>No new value for %n s: the device stopped sending this quantity (another output content, a polled record that stopped, or a link that went quiet).</source>
        <translation>
            <numerusform>No new value for %n s: the device stopped sending this quantity (another output content, a polled record that stopped, or a link that went quiet).</numerusform>
            <numerusform>No new value for %n s: the device stopped sending this quantity (another output content, a polled record that stopped, or a link that went quiet).</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>imudesk::record::ReplayWorker</name>
    <message numerus="yes">
        <location filename="../core/record/replay_worker.cpp" line="+78"/>
        <source>%n damaged chunk(s) skipped</source>
        <translation>
            <numerusform>%n damaged chunk skipped</numerusform>
            <numerusform>%n damaged chunks skipped</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>imudesk::station::ModuleRunner</name>
    <message numerus="yes">
        <location filename="../core/station/module_runner.cpp" line="+510"/>
        <source>%n setting(s) applied and read back</source>
        <translation>
            <numerusform>%n setting applied and read back</numerusform>
            <numerusform>%n settings applied and read back</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>imudesk::ui::AnalysisWindow</name>
    <message numerus="yes">
        <location filename="../ui/charts/analysis_window.cpp" line="+208"/>
        <source>%1 to %2 ms: %n frame(s)</source>
        <translation>
            <numerusform>%1 to %2 ms: %n frame</numerusform>
            <numerusform>%1 to %2 ms: %n frames</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+3"/>
        <source>%1 ms or more: %n frame(s)</source>
        <translation>
            <numerusform>%1 ms or more: %n frame</numerusform>
            <numerusform>%1 ms or more: %n frames</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>imudesk::ui::ChartPanel</name>
    <message numerus="yes">
        <location filename="../ui/charts/chart_panel.cpp" line="+424"/>
        <source>%n chart(s) saved as one PNG in %1 (%2)</source>
        <translation>
            <numerusform>%n chart saved as one PNG in %1 (%2)</numerusform>
            <numerusform>%n charts saved as one PNG in %1 (%2)</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>imudesk::ui::CompassPoseView</name>
    <message numerus="yes">
        <location filename="../ui/attitude/compass_pose_view.cpp" line="+109"/>
        <source>%n point(s)</source>
        <translation>
            <numerusform>%n point</numerusform>
            <numerusform>%n points</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>imudesk::ui::ExportDialog</name>
    <message numerus="yes">
        <location filename="../ui/recording/export_dialog.cpp" line="+268"/>
        <source>%n row(s) written to %1</source>
        <translation>
            <numerusform>%n row written to %1</numerusform>
            <numerusform>%n rows written to %1</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>imudesk::ui::FindDevicesDialog</name>
    <message numerus="yes">
        <location filename="../ui/discovery/find_devices_dialog.cpp" line="+142"/>
        <source>%n device(s) opened, each in a tab of its own.</source>
        <translation>
            <numerusform>%n device opened, in a tab of its own.</numerusform>
            <numerusform>%n devices opened, each in a tab of its own.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+178"/>
        <source>Sweeping %n port(s)</source>
        <translation>
            <numerusform>Sweeping %n port</numerusform>
            <numerusform>Sweeping %n ports</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+0"/>
        <source> and %n CAN bus(es)…</source>
        <translation>
            <numerusform> and %n CAN bus…</numerusform>
            <numerusform> and %n CAN buses…</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+133"/>
        <source>%n device(s) found</source>
        <translation>
            <numerusform>%n device found</numerusform>
            <numerusform>%n devices found</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source> %n conflict(s): see below, in red.</source>
        <translation>
            <numerusform> %n conflict: see below, in red.</numerusform>
            <numerusform> %n conflicts: see below, in red.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>imudesk::ui::LineDatabaseStatus</name>
    <message numerus="yes">
        <location filename="../ui/station/line_database_dialog.cpp" line="+217"/>
        <source> · %n result(s) waiting to upload</source>
        <translation>
            <numerusform> · %n result waiting to upload</numerusform>
            <numerusform> · %n results waiting to upload</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>imudesk::ui::MagCalibrationWizard</name>
    <message numerus="yes">
        <location filename="../ui/calibration/mag_calibration_wizard.cpp" line="+719"/>
        <source>The device now corrects its own output, so ImuDesk&apos;s fit keeps the %n raw sample(s) collected before.</source>
        <translation>
            <numerusform>The device now corrects its own output, so ImuDesk&apos;s fit keeps the %n raw sample collected before.</numerusform>
            <numerusform>The device now corrects its own output, so ImuDesk&apos;s fit keeps the %n raw samples collected before.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>imudesk::ui::ModbusScanDialog</name>
    <message numerus="yes">
        <location filename="../ui/bus/modbus_scan_dialog.cpp" line="+159"/>
        <source>Cancelled; %n device(s) found so far.</source>
        <translation>
            <numerusform>Cancelled; %n device found so far.</numerusform>
            <numerusform>Cancelled; %n devices found so far.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+4"/>
        <source>%n device(s) found.</source>
        <translation>
            <numerusform>%n device found.</numerusform>
            <numerusform>%n devices found.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>imudesk::ui::ModuleHistoryView</name>
    <message numerus="yes">
        <location filename="../ui/results/module_history_view.cpp" line="+151"/>
        <source>History of %1: %n attempt(s)</source>
        <translation>
            <numerusform>History of %1: %n attempt</numerusform>
            <numerusform>History of %1: %n attempts</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>imudesk::ui::RawBytesView</name>
    <message numerus="yes">
        <location filename="../ui/workspace/raw_bytes_view.cpp" line="+196"/>
        <source>… %n read(s) or write(s) not shown (the log dropped them before this view caught up) …</source>
        <translation>
            <numerusform>… %n read or write not shown (the log dropped them before this view caught up) …</numerusform>
            <numerusform>… %n reads or writes not shown (the log dropped them before this view caught up) …</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+3"/>
        <source>… %n byte(s) not shown (more arrived than the view holds) …</source>
        <translation>
            <numerusform>… %n byte not shown (more arrived than the view holds) …</numerusform>
            <numerusform>… %n bytes not shown (more arrived than the view holds) …</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>imudesk::ui::RecordingControls</name>
    <message numerus="yes">
        <location filename="../ui/recording/recording_controls.cpp" line="+294"/>
        <source>%n frame(s)</source>
        <translation>
            <numerusform>%n frame</numerusform>
            <numerusform>%n frames</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>imudesk::ui::ResultsWindow</name>
    <message numerus="yes">
        <location filename="../ui/results/results_window.cpp" line="+424"/>
        <source>The newest %n module(s) found; there are more: narrow the filter to see them.</source>
        <translation>
            <numerusform>The newest %n module found; there are more: narrow the filter to see them.</numerusform>
            <numerusform>The newest %n modules found; there are more: narrow the filter to see them.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+3"/>
        <source>%n module(s) found.</source>
        <translation>
            <numerusform>%n module found.</numerusform>
            <numerusform>%n modules found.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>imudesk::ui::SessionRecordingWindow</name>
    <message numerus="yes">
        <location filename="../ui/recording/session_recording_window.cpp" line="+189"/>
        <source>Recording %n device(s) into %1…</source>
        <translation>
            <numerusform>Recording %n device into %1…</numerusform>
            <numerusform>Recording %n devices into %1…</numerusform>
        </translation>
    </message>
</context>
</TS>
