<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="zh_TW">
<context>
    <name>PtySimulator</name>
    <message>
        <location filename="../core/sim/pty_simulator.cpp" line="+251" />
        <source>Cannot open a pseudo-terminal: %1</source>
        <translation>無法開啟虛擬終端機：%1</translation>
    </message>
</context>
<context>
    <name>imudesk::device::SessionWorker</name>
    <message>
        <location filename="../core/device/session_worker.cpp" line="+123" />
        <source>the connection was closed</source>
        <translation>連線已關閉</translation>
    </message>
    <message>
        <location line="+27" />
        <source>automatic reconnection was turned off</source>
        <translation>自動重新連線已關閉</translation>
    </message>
    <message>
        <location line="+19" />
        <source>the port is not open</source>
        <translation>串列埠未開啟</translation>
    </message>
    <message>
        <location line="+26" />
        <source>writing to the port failed</source>
        <translation>寫入串列埠失敗</translation>
    </message>
    <message>
        <location line="+29" />
        <source>no reply within %1 ms (the device ignores commands it does not know)</source>
        <translation>%1 ms 內無回應（裝置不回應它不認識的指令）</translation>
    </message>
    <message>
        <location line="+163" />
        <source>The device that came back on %1 is a different one (serial %2, before %3). Its data continues in this session.</source>
        <translation>%1 上重新出現的是另一台裝置（序號 %2，之前為 %3）。其資料將繼續記錄在此工作階段中。</translation>
    </message>
    <message>
        <location line="+13" />
        <source>disconnected — waiting for the device to come back</source>
        <translation>已中斷連線，正在等待裝置重新連線</translation>
    </message>
    <message>
        <location line="+33" />
        <source>%1 at %2 baud (reconnected)</source>
        <translation>%1，波特率 %2（已重新連線）</translation>
    </message>
    <message>
        <location line="+143" />
        <source>Bytes keep arriving on %1 but none of them form a frame: the device probably runs at another baud rate now. Disconnect and connect again with the baud rate set to Auto.</source>
        <translation>%1 上持續收到位元組，但無法組成任何資料框：裝置可能已改用其他波特率。請中斷連線，並將波特率設為「自動」後重新連線。</translation>
    </message>
    <message>
        <location line="+61" />
        <source>No HiPNUC device answered on %1 at any baud rate (115200, 921600, 460800, 230400, 256000, 57600, 38400, 19200, 9600, 4800). Check the cable and the power, and that no other program uses the port.</source>
        <translation>%1 上在所有波特率（115200、921600、460800、230400、256000、57600、38400、19200、9600、4800）下都沒有 HiPNUC 裝置回應。請檢查線材和電源，並確認沒有其他程式占用該串列埠。</translation>
    </message>
    <message>
        <location line="+15" />
        <source>trying %1 baud</source>
        <translation>正在嘗試 %1 波特率</translation>
    </message>
    <message>
        <location line="+54" />
        <source>%1 at %2 baud</source>
        <translation>%1，波特率 %2</translation>
    </message>
</context>
<context>
    <name>imudesk::io::SerialTransport</name>
    <message>
        <location filename="../core/io/serial_transport.cpp" line="+26" />
        <source>Port %1 was not found. Check that the device is plugged in and choose the port again from the list.</source>
        <translation>找不到串列埠 %1。請檢查裝置是否已插好，然後從清單中重新選擇串列埠。</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Port %1 is in use by another program (a serial terminal, CHCenter or another ImuDesk). Close that program and connect again.</source>
        <translation>串列埠 %1 正被其他程式占用（序列終端機、CHCenter 或另一個 ImuDesk）。請關閉該程式後重新連線。</translation>
    </message>
    <message>
        <location line="+5" />
        <source>No permission to open %1. On Linux add your user to the dialout group (sudo usermod -aG dialout $USER), then log out and in again.</source>
        <translation>沒有開啟 %1 的權限。在 Linux 上請將目前使用者加入 dialout 群組（sudo usermod -aG dialout $USER），然後登出再重新登入。</translation>
    </message>
    <message>
        <location line="+8" />
        <source>Could not open %1: %2</source>
        <translation>無法開啟 %1：%2</translation>
    </message>
    <message>
        <location line="+129" />
        <source>The connection to %1 was lost (%2). Check the cable; everything received so far is kept.</source>
        <translation>與 %1 的連線已中斷（%2）。請檢查線材；已接收的資料都會保留。</translation>
    </message>
</context>
<context>
    <name>imudesk::model::MainStatus</name>
    <message>
        <location filename="../core/model/main_status.cpp" line="+11" />
        <source>Gyro bias estimate not yet converged: keep the module still for 3-5 s to improve heading accuracy.</source>
        <translation>陀螺儀零偏估計尚未收斂：請保持模組靜止 3-5 s，以提高航向角精度。</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Magnetic disturbance: the field is disturbed, the magnetometer is not calibrated or the hard-iron environment changed; 9-axis heading may be wrong.</source>
        <translation>磁場干擾：磁場受到干擾、磁力計未校準或硬磁環境發生變化；9 軸航向角可能不準確。</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Accelerometer over range now or within the last 2 s.</source>
        <translation>加速度計目前或最近 2 s 內超出量程。</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Gyroscope over range now or within the last 2 s.</source>
        <translation>陀螺儀目前或最近 2 s 內超出量程。</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Attitude accuracy poor (large AHRS filter covariance): keep still for a moment.</source>
        <translation>姿態精度差（AHRS 濾波器共變異數較大）：請保持靜止片刻。</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The device detected that it is static.</source>
        <translation>裝置偵測到自身處於靜止狀態。</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The magnetometer takes part in heading (9-axis mode).</source>
        <translation>磁力計參與航向解算（9 軸模式）。</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Not synchronised to UTC: system_time is time since power-up.</source>
        <translation>未與 UTC 同步：system_time 為上電以來的時間。</translation>
    </message>
    <message>
        <location line="+1" />
        <source>This frame corresponds to a SYNC_OUT pulse.</source>
        <translation>該幀對應一個 SYNC_OUT 脈衝。</translation>
    </message>
</context>
<context>
    <name>imudesk::models::CommandLogModel</name>
    <message>
        <location filename="../core/models/command_log_model.cpp" line="+88" />
        <source>waiting</source>
        <translation>等待中</translation>
    </message>
    <message>
        <location line="+1" />
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <location line="+1" />
        <source>ERR</source>
        <translation>ERR</translation>
    </message>
    <message>
        <location line="+1" />
        <source>timeout</source>
        <translation>逾時</translation>
    </message>
    <message>
        <location line="+1" />
        <source>cancelled</source>
        <translation>已取消</translation>
    </message>
    <message>
        <location line="+1" />
        <source>not sent</source>
        <translation>未傳送</translation>
    </message>
    <message>
        <location line="+50" />
        <source>Time</source>
        <translation>時間</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Command</source>
        <translation>指令</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Status</source>
        <translation>狀態</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Reply</source>
        <translation>回應</translation>
    </message>
</context>
<context>
    <name>imudesk::models::LatestValuesModel</name>
    <message>
        <location filename="../core/models/latest_values_model.cpp" line="+144" />
        <source>Quantity</source>
        <translation>物理量</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Value</source>
        <translation>數值</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Unit</source>
        <translation>單位</translation>
    </message>
    <message>
        <location line="+82" />
        <source>0 invalid</source>
        <translation>0 解無效</translation>
    </message>
    <message>
        <location line="+1" />
        <source>1 aligning</source>
        <translation>1 對準中</translation>
    </message>
    <message>
        <location line="+1" />
        <source>3 navigating</source>
        <translation>3 組合導航中</translation>
    </message>
    <message>
        <location line="+1" />
        <source>6 dead reckoning</source>
        <translation>6 慣性遞推中</translation>
    </message>
    <message>
        <location line="+23" />
        <source>none (%1)</source>
        <translation>無 (%1)</translation>
    </message>
    <message>
        <location line="+14" />
        <source>Acceleration %1</source>
        <translation>加速度 %1</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Angular velocity %1</source>
        <translation>角速度 %1</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Magnetic field %1</source>
        <translation>磁場 %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Roll</source>
        <translation>橫滾角</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Pitch</source>
        <translation>俯仰角</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Yaw</source>
        <translation>航向角</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Quaternion %1</source>
        <translation>四元數 %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Air pressure</source>
        <translation>氣壓</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Temperature</source>
        <translation>溫度</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Device time</source>
        <translation>裝置時間</translation>
    </message>
    <message>
        <location line="+1" />
        <source>INS status</source>
        <translation>組合導航狀態</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Latitude</source>
        <translation>緯度</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Longitude</source>
        <translation>經度</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Altitude (MSL)</source>
        <translation>海拔高度</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Velocity east</source>
        <translation>東向速度</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Velocity north</source>
        <translation>北向速度</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Velocity up</source>
        <translation>天向速度</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Heave</source>
        <translation>垂蕩</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Surge</source>
        <translation>縱蕩</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Sway</source>
        <translation>橫蕩</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Inclination X</source>
        <translation>X 軸傾角</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Inclination Y</source>
        <translation>Y 軸傾角</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Status flags</source>
        <translation>狀態旗標</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Frame type</source>
        <translation>幀類型</translation>
    </message>
    <message>
        <location line="+9" />
        <source>G</source>
        <translation>G</translation>
    </message>
    <message>
        <location line="+0" />
        <source>m/s²</source>
        <translation>m/s²</translation>
    </message>
    <message>
        <location line="+1" />
        <source>deg/s</source>
        <translation>°/s</translation>
    </message>
    <message>
        <location line="+0" />
        <source>rad/s</source>
        <translation>rad/s</translation>
    </message>
    <message>
        <location line="+1" />
        <source>µT</source>
        <translation>µT</translation>
    </message>
    <message>
        <location line="+1" />
        <location line="+4" />
        <location line="+3" />
        <source>deg</source>
        <translation>°</translation>
    </message>
    <message>
        <location line="-6" />
        <source>Pa</source>
        <translation>Pa</translation>
    </message>
    <message>
        <location line="+1" />
        <source>°C</source>
        <translation>°C</translation>
    </message>
    <message>
        <location line="+1" />
        <source>ms</source>
        <translation>ms</translation>
    </message>
    <message>
        <location line="+1" />
        <location line="+2" />
        <source>m</source>
        <translation>m</translation>
    </message>
    <message>
        <location line="-1" />
        <source>m/s</source>
        <translation>m/s</translation>
    </message>
    <message>
        <location line="+13" />
        <source>Acceleration along the sensor's %1 axis, in G (1 G = 9.8 m/s², the vendor's constant).</source>
        <translation>沿感測器 %1 軸的加速度，單位 G（1 G = 9.8 m/s²，廠商採用的常數）。</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Angular velocity about the sensor's %1 axis, in deg/s.</source>
        <translation>繞感測器 %1 軸的角速度，單位 °/s。</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Magnetic field along the sensor's %1 axis, in µT.</source>
        <translation>沿感測器 %1 軸的磁場強度，單位 µT。</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Roll angle, in degrees (Euler angles in the device's convention, ENU 312 by default).</source>
        <translation>橫滾角，單位 °（裝置約定的歐拉角，預設 ENU 312 順序）。</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Pitch angle, in degrees (Euler angles in the device's convention, ENU 312 by default).</source>
        <translation>俯仰角，單位 °（裝置約定的歐拉角，預設 ENU 312 順序）。</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Yaw (heading) angle, in degrees (Euler angles in the device's convention, ENU 312 by default).</source>
        <translation>航向角，單位 °（裝置約定的歐拉角，預設 ENU 312 順序）。</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Attitude quaternion, component %1 (body to navigation frame), no unit.</source>
        <translation>姿態四元數的 %1 分量（載體座標系到導航座標系），無單位。</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Air pressure from the barometer, in Pa.</source>
        <translation>氣壓計測得的氣壓，單位 Pa。</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Sensor temperature, in °C.</source>
        <translation>感測器溫度，單位 °C。</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Device timestamp in ms: UTC time of day when synchronised, otherwise time since power-up.</source>
        <translation>裝置時間戳記，單位 ms：與 UTC 同步時為當天的 UTC 時間，否則為上電以來的時間。</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Integrated navigation state: 0 invalid, 1 aligning, 3 navigating, 6 dead reckoning.</source>
        <translation>組合導航解狀態：0 解無效，1 對準中，3 組合導航中，6 慣性遞推中。</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Position from integrated navigation, in degrees (south and west negative).</source>
        <translation>組合導航解算的位置，單位 °（南緯和西經為負）。</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Height above mean sea level, in m.</source>
        <translation>平均海平面以上的高度，單位 m。</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Velocity in the east-north-up frame, in m/s.</source>
        <translation>東北天（ENU）座標系下的速度，單位 m/s。</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Ship motion displacement (heave, surge, sway), in m.</source>
        <translation>船舶運動位移（垂蕩、縱蕩、橫蕩），單位 m。</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Inclinometer angle about the %1 axis, in degrees.</source>
        <translation>傾角儀繞 %1 軸的角度，單位 °。</translation>
    </message>
    <message>
        <location line="+2" />
        <source>MAIN_STATUS flags set in the latest frame (firmware 1.7.0 and later), then the raw word in hex.</source>
        <translation>最新一幀中設定的 MAIN_STATUS 旗標（韌體 1.7.0 及以上），括號內為十六進位原始值。</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The frame type (packet tag) that carried the latest values, e.g. HI91.</source>
        <translation>攜帶最新數值的幀類型（封包標籤），例如 HI91。</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::AttitudeWidget</name>
    <message>
        <location filename="../ui/attitude_widget.cpp" line="+245" />
        <source>X</source>
        <translation>X</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Y</source>
        <translation>Y</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Z</source>
        <translation>Z</translation>
    </message>
    <message>
        <location line="+1" />
        <source>N</source>
        <translation>N</translation>
    </message>
    <message>
        <location line="+2" />
        <source>E (x)</source>
        <translation>E (x)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>N (y)</source>
        <translation>N (y)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>U (z)</source>
        <translation>U (z)</translation>
    </message>
    <message>
        <location line="+1" />
        <location line="+351" />
        <source>ENU 3-1-2</source>
        <translation>ENU 3-1-2</translation>
    </message>
    <message>
        <location line="-349" />
        <source>N (x)</source>
        <translation>N (x)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>E (y)</source>
        <translation>E (y)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>D (z)</source>
        <translation>D (z)</translation>
    </message>
    <message>
        <location line="+1" />
        <location line="+347" />
        <source>NED 3-2-1</source>
        <translation>NED 3-2-1</translation>
    </message>
    <message>
        <location line="-345" />
        <source>No attitude yet</source>
        <translation>尚無姿態資料</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Roll</source>
        <translation>橫滾角</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Pitch</source>
        <translation>俯仰角</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Yaw</source>
        <translation>航向角</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Heading</source>
        <translation>方位角</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Drag to turn the view, double-click to reset it</source>
        <translation>拖曳以旋轉檢視，按兩下以重設</translation>
    </message>
    <message>
        <location line="+351" />
        <source>Reset view</source>
        <translation>重設檢視</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::ChartPanel</name>
    <message>
        <location filename="../ui/chart_panel.cpp" line="+66" />
        <source>&amp;Time axis:</source>
        <translation>時間軸(&amp;T)：</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Device clock</source>
        <translation>裝置時鐘</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Host arrival time</source>
        <translation>主機接收時間</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Device clock: the module's own timestamps, where lost samples show as gaps. Host arrival time: when the samples reached this computer.</source>
        <translation>裝置時鐘：模組自身的時間戳記，遺失的取樣顯示為間斷。主機接收時間：取樣到達本電腦的時間。</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::ChartView</name>
    <message>
        <location filename="../ui/chart_view.cpp" line="+107" />
        <source>Accelerometer</source>
        <translation>加速度計</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Gyroscope</source>
        <translation>陀螺儀</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Magnetometer</source>
        <translation>磁力計</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Euler angles</source>
        <translation>歐拉角</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Quaternion</source>
        <translation>四元數</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Air pressure</source>
        <translation>氣壓</translation>
    </message>
    <message>
        <location line="+1" />
        <location line="+14" />
        <location line="+39" />
        <source>Temperature</source>
        <translation>溫度</translation>
    </message>
    <message>
        <location line="-45" />
        <source>Acceleration</source>
        <translation>加速度</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Angular velocity</source>
        <translation>角速度</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Magnetic field</source>
        <translation>磁場</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Angle</source>
        <translation>角度</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Quaternion component</source>
        <translation>四元數分量</translation>
    </message>
    <message>
        <location line="+1" />
        <location line="+39" />
        <source>Pressure</source>
        <translation>氣壓</translation>
    </message>
    <message>
        <location line="-30" />
        <source>G</source>
        <translation>G</translation>
    </message>
    <message>
        <location line="+1" />
        <source>deg/s</source>
        <translation>°/s</translation>
    </message>
    <message>
        <location line="+1" />
        <source>µT</source>
        <translation>µT</translation>
    </message>
    <message>
        <location line="+1" />
        <source>deg</source>
        <translation>°</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Pa</source>
        <translation>Pa</translation>
    </message>
    <message>
        <location line="+1" />
        <source>°C</source>
        <translation>°C</translation>
    </message>
    <message>
        <location line="+21" />
        <source>Roll</source>
        <translation>橫滾角</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Pitch</source>
        <translation>俯仰角</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Yaw</source>
        <translation>航向角</translation>
    </message>
    <message>
        <location line="+10" />
        <source>Acceleration %1</source>
        <translation>加速度 %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Angular velocity %1</source>
        <translation>角速度 %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Magnetic field %1</source>
        <translation>磁場 %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Quaternion %1</source>
        <translation>四元數 %1</translation>
    </message>
    <message>
        <location line="+40" />
        <source>Device time (s)</source>
        <translation>裝置時間（s）</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Host arrival time (s)</source>
        <translation>主機接收時間（s）</translation>
    </message>
    <message>
        <location line="+6" />
        <source>%1 min</source>
        <translation>%1 min</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <location line="+20" />
        <source>the chart could not be drawn</source>
        <translation>無法繪製圖表</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Could not save the chart as %1: %2</source>
        <translation>無法將圖表儲存為 %1：%2</translation>
    </message>
    <message>
        <location line="+150" />
        <source>%1 (%2)</source>
        <comment>quantity (unit)</comment>
        <translation>%1（%2）</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Show or hide %1</source>
        <translation>顯示或隱藏 %1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>&amp;Window:</source>
        <translation>時間窗(&amp;W)：</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Time span shown by this chart</source>
        <translation>此圖表顯示的時間跨度</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Auto scale</source>
        <translation>自動縮放</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Fit the vertical axis to the data shown; off: use the range on the right</source>
        <translation>使縱軸適應所顯示的資料；關閉時使用右側設定的範圍</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Lower end of the vertical axis (no unit)</source>
        <translation>縱軸下限（無單位）</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Upper end of the vertical axis (no unit)</source>
        <translation>縱軸上限（無單位）</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Lower end of the vertical axis, in %1</source>
        <translation>縱軸下限，單位 %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Upper end of the vertical axis, in %1</source>
        <translation>縱軸上限，單位 %1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Save as PNG…</source>
        <translation>另存為 PNG…</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Save this chart as a PNG image</source>
        <translation>將此圖表儲存為 PNG 影像</translation>
    </message>
    <message>
        <location line="+9" />
        <source>Resume</source>
        <translation>繼續</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Pause</source>
        <translation>暫停</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Follow the newest data again</source>
        <translation>重新跟隨最新資料</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Freeze this chart; the data keeps being recorded</source>
        <translation>凍結此圖表；資料仍會繼續記錄</translation>
    </message>
    <message>
        <location line="+216" />
        <source>m/s²</source>
        <translation>m/s²</translation>
    </message>
    <message>
        <location line="+2" />
        <source>rad/s</source>
        <translation>rad/s</translation>
    </message>
    <message>
        <location line="+135" />
        <source>t = %1 s</source>
        <translation>t = %1 s</translation>
    </message>
    <message>
        <location line="+20" />
        <source>%1 %2 %3</source>
        <comment>crosshair read-out: axis, value, unit</comment>
        <translation>%1 %2 %3</translation>
    </message>
    <message>
        <location line="+23" />
        <location line="+7" />
        <source>Save Chart as PNG</source>
        <translation>將圖表儲存為 PNG</translation>
    </message>
    <message>
        <location line="-7" />
        <source>PNG images (*.png)</source>
        <translation>PNG 影像 (*.png)</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::CommandLogWidget</name>
    <message>
        <location filename="../ui/command_log_widget.cpp" line="+169" />
        <source>Copy</source>
        <translation>複製</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Copy the selected commands as tab-separated text</source>
        <translation>將所選指令複製為以定位字元分隔的文字</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Copy all</source>
        <translation>全部複製</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Copy every command as tab-separated text</source>
        <translation>將所有指令複製為以定位字元分隔的文字</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Clear</source>
        <translation>清除</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Remove every command from the list</source>
        <translation>從清單中移除所有指令</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::ComparisonChart</name>
    <message>
        <location filename="../ui/comparison_chart.cpp" line="+113" />
        <source>Comparison</source>
        <translation>比較</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Channel:</source>
        <translation>通道(&amp;C)：</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The quantity compared across the devices</source>
        <translation>在各裝置之間比較的物理量</translation>
    </message>
    <message>
        <location line="+5" />
        <location line="+16" />
        <source>%1 (%2)</source>
        <comment>quantity (unit)</comment>
        <translation>%1（%2）</translation>
    </message>
    <message>
        <location line="-14" />
        <source>&amp;Window:</source>
        <translation>時間窗(&amp;W)：</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Time span shown</source>
        <translation>顯示的時間跨度</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Save as PNG…</source>
        <translation>另存為 PNG…</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Save this chart as a PNG image</source>
        <translation>將此圖表儲存為 PNG 影像</translation>
    </message>
    <message>
        <location line="+17" />
        <source>Resume</source>
        <translation>繼續</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Pause</source>
        <translation>暫停</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Follow the newest data again</source>
        <translation>重新跟隨最新資料</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Freeze this chart; the data keeps being recorded</source>
        <translation>凍結此圖表；資料仍會繼續記錄</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::ConnectionBar</name>
    <message>
        <location filename="../ui/connection_bar.cpp" line="+148" />
        <source>SN %1</source>
        <translation>序號 %1</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Manufacturer: %1</source>
        <translation>製造商：%1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>USB ID: %1:%2</source>
        <translation>USB ID：%1:%2</translation>
    </message>
    <message>
        <location line="+41" />
        <source>&amp;Port:</source>
        <translation>串列埠(&amp;P)：</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Serial port of the IMU, or a simulated device that runs inside ImuDesk</source>
        <translation>IMU 所連接的串列埠，或在 ImuDesk 內部執行的模擬裝置</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Refresh</source>
        <translation>重新整理</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Scan for serial ports again (the list also refreshes every 2 s)</source>
        <translation>重新掃描串列埠（清單也會每 2 s 自動重新整理）</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Baud rate:</source>
        <translation>波特率(&amp;B)：</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Auto</source>
        <translation>自動</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Auto tries every HiPNUC baud rate, starting with 115200</source>
        <translation>自動：從 115200 開始依序嘗試 HiPNUC 支援的所有波特率</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Disconnect</source>
        <translation>中斷連線</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Close the connection (Ctrl+D)</source>
        <translation>關閉連線（Ctrl+D）</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Connect</source>
        <translation>連線</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Connect to the selected port (Ctrl+K)</source>
        <translation>連線到所選串列埠（Ctrl+K）</translation>
    </message>
    <message>
        <location line="+7" />
        <source>Simulated %1 (firmware %2)</source>
        <translation>模擬 %1（韌體 %2）</translation>
    </message>
    <message>
        <location line="+4" />
        <source>%1 (%2)</source>
        <translation>%1（%2）</translation>
    </message>
    <message>
        <location line="+25" />
        <source>No serial port found</source>
        <translation>找不到串列埠</translation>
    </message>
    <message>
        <location line="+5" />
        <source>A simulated device on a pseudo-terminal, driven exactly like hardware</source>
        <translation>執行在虛擬終端機上的模擬裝置，操作方式與真實硬體完全相同</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::ConsoleWidget</name>
    <message>
        <location filename="../ui/console_widget.cpp" line="+127" />
        <source>(reply to: %1)</source>
        <translation>（對 %1 的回應）</translation>
    </message>
    <message>
        <location line="+7" />
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <location line="+1" />
        <source>ERR: %1</source>
        <translation>錯誤：%1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Timeout: %1</source>
        <translation>逾時：%1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Cancelled: %1</source>
        <translation>已取消：%1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Not sent: %1</source>
        <translation>未傳送：%1</translation>
    </message>
    <message>
        <location line="+59" />
        <source>Type an ASCII command, e.g. LOG VERSION, and press Enter</source>
        <translation>輸入 ASCII 指令（例如 LOG VERSION）後按 Enter</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Enter sends the command; Up and Down recall earlier commands</source>
        <translation>Enter 傳送指令；上、下方向鍵叫出先前的指令</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Send</source>
        <translation>傳送</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Clear log</source>
        <translation>清除日誌</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::DeviceWorkspace</name>
    <message>
        <location filename="../ui/device_workspace.cpp" line="+212" />
        <source>New connection</source>
        <translation>新連線</translation>
    </message>
    <message>
        <location line="+2" />
        <source>%1 on %2</source>
        <translation>%2 上的 %1</translation>
    </message>
    <message>
        <location line="+42" />
        <source>Disconnect first, then connect to the simulated device.</source>
        <translation>請先中斷連線，再連線到模擬裝置。</translation>
    </message>
    <message>
        <location line="+9" />
        <source>The simulated device could not start: %1</source>
        <translation>模擬裝置無法啟動：%1</translation>
    </message>
    <message>
        <location line="+8" />
        <source>Simulated %1 (firmware %2)</source>
        <translation>模擬 %1（韌體 %2）</translation>
    </message>
    <message>
        <location line="+129" />
        <source>Not connected</source>
        <translation>未連線</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Opening %1…</source>
        <translation>正在開啟 %1…</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Detecting the baud rate of %1…</source>
        <translation>正在偵測 %1 的波特率…</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Connected</source>
        <translation>已連線</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Connection to %1 lost</source>
        <translation>與 %1 的連線已中斷</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Disconnected from %1 — waiting for the device to come back</source>
        <translation>已與 %1 中斷連線，正在等待裝置重新連線</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Could not connect to %1</source>
        <translation>無法連線到 %1</translation>
    </message>
    <message>
        <location line="+13" />
        <source>firmware %1</source>
        <translation>韌體 %1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>SN %1</source>
        <translation>序號 %1</translation>
    </message>
    <message>
        <location line="+6" />
        <source>Product: %1</source>
        <translation>產品：%1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Build: %1</source>
        <translation>建置：%1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Bootloader: %1</source>
        <translation>開機載入程式：%1</translation>
    </message>
    <message>
        <location line="+8" />
        <location line="+8" />
        <source>%1 baud</source>
        <translation>波特率 %1</translation>
    </message>
    <message>
        <location line="+4" />
        <source>%1 %2 Hz</source>
        <translation>%1 %2 Hz</translation>
    </message>
    <message>
        <location line="+1" />
        <source>no frames</source>
        <translation>無數據幀</translation>
    </message>
    <message>
        <location line="+1" />
        <source>load %1%</source>
        <translation>負載 %1%</translation>
    </message>
    <message>
        <location line="+1" />
        <source>CRC errors %1</source>
        <translation>CRC 錯誤 %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>lost %1</source>
        <translation>遺失 %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>skipped %1 B</source>
        <translation>略過 %1 B</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Received %1 bytes, %2 frames, %3 NMEA sentences.
Errors: %4 CRC, %5 length, %6 payload, %7 NMEA; %8 bytes skipped.
Frames lost (gaps in the device time): %9.
Link load = bytes per second × 10 bits / baud rate.</source>
        <translation>已接收 %1 位元組、%2 幀、%3 條 NMEA 語句。
錯誤：CRC %4 個，長度 %5 個，酬載 %6 個，NMEA %7 個；略過 %8 位元組。
遺失的幀（裝置時間中的間斷）：%9。
鏈路負載 = 每秒位元組數 × 10 位元 / 波特率。</translation>
    </message>
    <message>
        <location line="+48" />
        <source>Console</source>
        <translation>主控台</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Raw bytes</source>
        <translation>原始位元組</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Command log</source>
        <translation>指令日誌</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Values and attitude</source>
        <translation>數值與姿態</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::LanguageSwitcher</name>
    <message>
        <location filename="../ui/language_switcher.cpp" line="+52" />
        <source>Unknown language "%1"; choose one of: %2.</source>
        <translation>未知語言「%1」；請選擇以下其中之一：%2。</translation>
    </message>
    <message>
        <location line="+14" />
        <source>The %1 translation was not found in %2.</source>
        <translation>在 %2 中找不到 %1 翻譯。</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::MainWindow</name>
    <message>
        <location filename="../ui/main_window.cpp" line="+239" />
        <source>Choose a port first.</source>
        <translation>請先選擇串列埠。</translation>
    </message>
    <message>
        <location line="+50" />
        <source>Could not save the screenshot to %1: %2</source>
        <translation>無法將螢幕擷取畫面儲存到 %1：%2</translation>
    </message>
    <message>
        <location line="+19" />
        <source>ImuDesk</source>
        <translation>ImuDesk</translation>
    </message>
    <message>
        <location line="+9" />
        <source>About ImuDesk</source>
        <translation>關於 ImuDesk</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&lt;h3&gt;ImuDesk %1&lt;/h3&gt;&lt;p&gt;A bench tool for HiPNUC IMU modules: live values, the ASCII command console and simulated devices.&lt;/p&gt;&lt;p&gt;Built with Qt %2.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;ImuDesk %1&lt;/h3&gt;&lt;p&gt;HiPNUC IMU 模組測試工具：即時數值、ASCII 指令主控台和模擬裝置。&lt;/p&gt;&lt;p&gt;以 Qt %2 建置。&lt;/p&gt;</translation>
    </message>
    <message>
        <location line="+18" />
        <source>ImuDesk – IMU bench tool</source>
        <translation>ImuDesk – IMU 測試工具</translation>
    </message>
    <message>
        <location line="+3" />
        <source>%1 – %2</source>
        <translation>%1 – %2</translation>
    </message>
    <message>
        <location line="+48" />
        <source>Save screenshot</source>
        <translation>儲存螢幕擷取畫面</translation>
    </message>
    <message>
        <location line="+1" />
        <source>PNG images (*.png)</source>
        <translation>PNG 影像 (*.png)</translation>
    </message>
    <message>
        <location line="+60" />
        <source>&amp;File</source>
        <translation>檔案(&amp;F)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Device</source>
        <translation>裝置(&amp;D)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;View</source>
        <translation>檢視(&amp;V)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Help</source>
        <translation>說明(&amp;H)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;New connection tab</source>
        <translation>新增連線分頁(&amp;N)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Open a tab for another device; each tab has its own connection and views</source>
        <translation>為另一台裝置開啟一個分頁；每個分頁都有獨立的連線和檢視</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Close tab</source>
        <translation>關閉分頁(&amp;C)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Save &amp;screenshot…</source>
        <translation>儲存螢幕擷取畫面(&amp;S)…</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Quit</source>
        <translation>結束(&amp;Q)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Connect</source>
        <translation>連線(&amp;C)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Connect to the port chosen in the connection bar</source>
        <translation>連線到連線列中所選的串列埠</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Disconnect</source>
        <translation>中斷連線(&amp;D)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Send LOG &amp;VERSION</source>
        <translation>傳送 LOG &amp;VERSION</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Ask the device for its product name, firmware and serial number</source>
        <translation>查詢裝置的產品型號、韌體版本和序號</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;About ImuDesk</source>
        <translation>關於 ImuDesk(&amp;A)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Preferences…</source>
        <translation>偏好設定(&amp;P)…</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Compare devices</source>
        <translation>裝置比較</translation>
    </message>
    <message>
        <location line="-1" />
        <source>Connection</source>
        <translation>連線</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::PreferencesDialog</name>
    <message>
        <location filename="../ui/preferences_dialog.cpp" line="+21" />
        <source>Preferences</source>
        <translation>偏好設定</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Language</source>
        <translation>語言</translation>
    </message>
    <message>
        <location line="+3" />
        <source>System language</source>
        <translation>跟隨系統</translation>
    </message>
    <message>
        <location line="+4" />
        <source>The language of the user interface. Takes effect the next time ImuDesk starts.</source>
        <translation>使用者介面的語言。下次啟動 ImuDesk 時生效。</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Language:</source>
        <translation>語言(&amp;L)：</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The new language is used after a restart.</source>
        <translation>新語言在重新啟動後生效。</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Display</source>
        <translation>顯示</translation>
    </message>
    <message>
        <location line="+3" />
        <source>G (1 G = 9.8 m/s²)</source>
        <translation>G（1 G = 9.8 m/s²）</translation>
    </message>
    <message>
        <location line="+1" />
        <source>m/s²</source>
        <translation>m/s²</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Unit of the accelerometer values and chart. Recorded data keeps the device's unit (G).</source>
        <translation>加速度計數值和曲線的單位。記錄的資料保持裝置的單位（G）。</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Acceleration:</source>
        <translation>加速度(&amp;A)：</translation>
    </message>
    <message>
        <location line="+2" />
        <source>deg/s</source>
        <translation>deg/s</translation>
    </message>
    <message>
        <location line="+1" />
        <source>rad/s</source>
        <translation>rad/s</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Unit of the gyroscope values and chart. Recorded data keeps the device's unit (deg/s).</source>
        <translation>陀螺儀數值和曲線的單位。記錄的資料保持裝置的單位（deg/s）。</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Angular &amp;rate:</source>
        <translation>角速度(&amp;R)：</translation>
    </message>
    <message>
        <location line="+2" />
        <source>ENU (east, north, up)</source>
        <translation>ENU（東、北、天）</translation>
    </message>
    <message>
        <location line="+1" />
        <source>NED (north, east, down)</source>
        <translation>NED（北、東、地）</translation>
    </message>
    <message>
        <location line="+1" />
        <source>World frame of the 3D attitude view.</source>
        <translation>三維姿態視圖的世界座標系。</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Attitude &amp;frame:</source>
        <translation>姿態座標系(&amp;F)：</translation>
    </message>
    <message>
        <location line="+3" />
        <source> Hz</source>
        <translation> Hz</translation>
    </message>
    <message>
        <location line="+1" />
        <source>How often charts and values are redrawn (%1 to %2 Hz). Lower rates use less CPU.</source>
        <translation>曲線和數值的刷新頻率（%1 至 %2 Hz）。頻率越低佔用 CPU 越少。</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Chart &amp;refresh:</source>
        <translation>曲線刷新(&amp;R)：</translation>
    </message>
    <message>
        <location line="+3" />
        <source> min</source>
        <translation> 分鐘</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The longest time window a chart can show (%1 to %2 minutes).</source>
        <translation>曲線可顯示的最長時間視窗（%1 至 %2 分鐘）。</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Chart &amp;history:</source>
        <translation>曲線歷史(&amp;H)：</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Recording</source>
        <translation>記錄</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Documents folder</source>
        <translation>文件資料夾</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Where new recordings are written.</source>
        <translation>新記錄儲存的位置。</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Browse…</source>
        <translation>瀏覽(&amp;B)…</translation>
    </message>
    <message>
        <location line="+4" />
        <source>&amp;Folder:</source>
        <translation>資料夾(&amp;F)：</translation>
    </message>
    <message>
        <location line="+2" />
        <source>File name of a new recording. {device}, {serial}, {date} and {time} are replaced.</source>
        <translation>新記錄的檔名。{device}、{serial}、{date} 和 {time} 會被替換。</translation>
    </message>
    <message>
        <location line="+1" />
        <source>File &amp;pattern:</source>
        <translation>檔名模式(&amp;P)：</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Example:</source>
        <translation>範例：</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Connection</source>
        <translation>連線</translation>
    </message>
    <message>
        <location line="+2" />
        <source>&amp;Reconnect by itself when an unplugged device comes back</source>
        <translation>拔出的裝置重新插入時自動重新連線(&amp;R)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>After a cable is pulled, wait for the same device (USB serial number, else port) and reconnect at the last baud rate.</source>
        <translation>線纜拔出後，等待同一裝置（按 USB 序號，否則按連接埠）重新出現，並以上次的波特率重新連線。</translation>
    </message>
    <message>
        <location line="+59" />
        <source>Recording folder</source>
        <translation>記錄資料夾</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::RawBytesView</name>
    <message numerus="yes">
        <location filename="../ui/raw_bytes_view.cpp" line="+196" />
        <source>… %n read(s) or write(s) not shown (the log dropped them before this view caught up) …</source>
        <translation>
            <numerusform>… 有 %n 次讀取或寫入未顯示（在此檢視跟上之前，日誌已將其捨棄）…</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+3" />
        <source>… %n byte(s) not shown (more arrived than the view holds) …</source>
        <translation>
            <numerusform>… 有 %n 位元組未顯示（到達的資料超出檢視容量）…</numerusform>
        </translation>
    </message>
    <message>
        <location line="+64" />
        <source>Pause</source>
        <translation>暫停</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Stop updating the view; the bytes are still recorded</source>
        <translation>停止更新檢視；位元組仍會繼續記錄</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Clear</source>
        <translation>清除</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Empty the view</source>
        <translation>清除檢視</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Copy</source>
        <translation>複製</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Copy the selected lines, or everything shown, to the clipboard</source>
        <translation>將所選行（未選取時為全部顯示內容）複製到剪貼簿</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Link traffic: time (s), direction (RX from the device, TX to it), byte offset, hex and ASCII</source>
        <translation>鏈路流量：時間（s）、方向（RX 為來自裝置，TX 為傳往裝置）、位元組偏移、十六進位和 ASCII</translation>
    </message>
    <message>
        <location line="+7" />
        <source>RX %1 bytes, TX %2 bytes</source>
        <translation>RX %1 位元組，TX %2 位元組</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Paused — %1</source>
        <translation>已暫停 — %1</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::StatusFlagsWidget</name>
    <message>
        <location filename="../ui/status_flags_widget.cpp" line="+95" />
        <source>Status:</source>
        <translation>狀態：</translation>
    </message>
    <message>
        <location line="+6" />
        <source>&lt;b&gt;%1&lt;/b&gt; (bit %2): %3</source>
        <translation>&lt;b&gt;%1&lt;/b&gt;（位元 %2）：%3</translation>
    </message>
    <message>
        <location line="+2" />
        <source>MAIN_STATUS flags of the latest frame: green = set, grey = clear, outlined = the frame carries no status word (firmware before 1.7.0, or another frame type)</source>
        <translation>最新一幀的 MAIN_STATUS 旗標：綠色 = 已設定，灰色 = 未設定，僅外框 = 該幀不含狀態字（韌體低於 1.7.0 或其他幀類型）</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <location filename="../app/gui/main.cpp" line="+82" />
        <source>ImuDesk: a bench tool for HiPNUC IMU modules.</source>
        <translation>ImuDesk：HiPNUC IMU 模組測試工具。</translation>
    </message>
    <message>
        <location line="+5" />
        <source>User interface language: zh_CN, zh_TW or en (default: the system's).</source>
        <translation>介面語言：zh_CN、zh_TW 或 en（預設跟隨系統）。</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Start connected to a simulated device (model MODEL, default HI14) that streams HI91 at 100 Hz.</source>
        <translation>啟動後連線到一個以 100 Hz 輸出 HI91 的模擬裝置（型號 MODEL，預設 HI14）。</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Firmware of the simulated device: 1.7.1 or 1.6.6 (default 1.7.1).</source>
        <translation>模擬裝置的韌體版本：1.7.1 或 1.6.6（預設 1.7.1）。</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Motion of the simulated device: static, spin or tumble (default static).</source>
        <translation>模擬裝置的運動方式：static（靜止）、spin（旋轉）或 tumble（翻滾）（預設 static）。</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Start connected to this serial port.</source>
        <translation>啟動後連線到此串列埠。</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Baud rate for --port or --simulate (default: detect automatically).</source>
        <translation>--port 或 --simulate 使用的波特率（預設自動偵測）。</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Start connected to a simulated HI14 (firmware 1.7.1) that tumbles slowly through every orientation.</source>
        <translation>啟動後連線到一個模擬 HI14（韌體 1.7.1），它會緩慢翻滾，經歷所有姿態。</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Save the main window to this PNG file and quit (see --after).</source>
        <translation>將主視窗儲存為此 PNG 檔案後結束（參見 --after）。</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Seconds to wait before --screenshot (default 3).</source>
        <translation>執行 --screenshot 前等待的秒數（預設 3）。</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Model to simulate with --simulate (default HI14).</source>
        <translation>--simulate 模擬的型號（預設 HI14）。</translation>
    </message>
    <message>
        <location line="+8" />
        <source>A model name is only accepted after --simulate.</source>
        <translation>型號名稱只能接在 --simulate 之後。</translation>
    </message>
    <message>
        <location line="+6" />
        <source>--after needs a number of seconds from 0 to 3600.</source>
        <translation>--after 需要 0 到 3600 之間的秒數。</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Use either --simulate or --port, not both.</source>
        <translation>--simulate 和 --port 只能擇一使用。</translation>
    </message>
    <message>
        <location line="+11" />
        <source>Unsupported baud rate "%1"; use auto or one of: %2.</source>
        <translation>不支援的波特率「%1」；請使用 auto 或以下其中之一：%2。</translation>
    </message>
    <message>
        <location line="+9" />
        <source>Invalid firmware version "%1"; use e.g. 1.7.1 or 1.6.6.</source>
        <translation>無效的韌體版本「%1」；請使用例如 1.7.1 或 1.6.6。</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Unknown motion "%1"; use static, spin or tumble.</source>
        <translation>未知的運動方式「%1」；請使用 static、spin 或 tumble。</translation>
    </message>
    <message>
        <location line="+20" />
        <source>ImuDesk</source>
        <translation>ImuDesk</translation>
    </message>
</context>
</TS>