<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="zh_CN">
<context>
    <name>PtySimulator</name>
    <message>
        <location filename="../core/sim/pty_simulator.cpp" line="+251"/>
        <source>Cannot open a pseudo-terminal: %1</source>
        <translation>无法打开伪终端：%1</translation>
    </message>
</context>
<context>
    <name>imudesk::device::SessionWorker</name>
    <message>
        <location filename="../core/device/session_worker.cpp" line="+91"/>
        <source>the connection was closed</source>
        <translation>连接已关闭</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>the port is not open</source>
        <translation>串口未打开</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>writing to the port failed</source>
        <translation>向串口写入失败</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>no reply within %1 ms (the device ignores commands it does not know)</source>
        <translation>%1 ms 内无应答（设备不响应它不认识的命令）</translation>
    </message>
    <message>
        <location line="+171"/>
        <source>No HiPNUC device answered on %1 at any baud rate (115200, 921600, 460800, 230400, 256000, 57600, 38400, 19200, 9600, 4800). Check the cable and the power, and that no other program uses the port.</source>
        <translation>%1 上在所有波特率（115200、921600、460800、230400、256000、57600、38400、19200、9600、4800）下都没有 HiPNUC 设备应答。请检查线缆和电源，并确认没有其他程序占用该串口。</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>trying %1 baud</source>
        <translation>正在尝试 %1 波特率</translation>
    </message>
    <message>
        <location line="+52"/>
        <source>%1 at %2 baud</source>
        <translation>%1，波特率 %2</translation>
    </message>
</context>
<context>
    <name>imudesk::io::SerialTransport</name>
    <message>
        <location filename="../core/io/serial_transport.cpp" line="+20"/>
        <source>Port %1 was not found. Check that the device is plugged in and choose the port again from the list.</source>
        <translation>未找到串口 %1。请检查设备是否已插好，然后从列表中重新选择串口。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Port %1 is in use by another program (a serial terminal, CHCenter or another ImuDesk). Close that program and connect again.</source>
        <translation>串口 %1 正被其他程序占用（串口终端、CHCenter 或另一个 ImuDesk）。请关闭该程序后重新连接。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>No permission to open %1. On Linux add your user to the dialout group (sudo usermod -aG dialout $USER), then log out and in again.</source>
        <translation>没有打开 %1 的权限。在 Linux 上请将当前用户加入 dialout 组（sudo usermod -aG dialout $USER），然后注销并重新登录。</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Could not open %1: %2</source>
        <translation>无法打开 %1：%2</translation>
    </message>
    <message>
        <location line="+103"/>
        <source>The connection to %1 was lost (%2). Check the cable; everything received so far is kept.</source>
        <translation>与 %1 的连接已断开（%2）。请检查线缆；已接收的数据都会保留。</translation>
    </message>
</context>
<context>
    <name>imudesk::model::MainStatus</name>
    <message>
        <location filename="../core/model/main_status.cpp" line="+11"/>
        <source>Gyro bias estimate not yet converged: keep the module still for 3-5 s to improve heading accuracy.</source>
        <translation>陀螺零偏估计尚未收敛：请保持模块静止 3-5 s，以提高航向角精度。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Magnetic disturbance: the field is disturbed, the magnetometer is not calibrated or the hard-iron environment changed; 9-axis heading may be wrong.</source>
        <translation>磁场干扰：磁场受到干扰、磁力计未校准或硬磁环境发生变化；9 轴航向角可能不准确。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Accelerometer over range now or within the last 2 s.</source>
        <translation>加速度计当前或最近 2 s 内超量程。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Gyroscope over range now or within the last 2 s.</source>
        <translation>陀螺仪当前或最近 2 s 内超量程。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Attitude accuracy poor (large AHRS filter covariance): keep still for a moment.</source>
        <translation>姿态精度差（AHRS 滤波器协方差较大）：请保持静止片刻。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The device detected that it is static.</source>
        <translation>设备检测到自身处于静止状态。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The magnetometer takes part in heading (9-axis mode).</source>
        <translation>磁力计参与航向解算（9 轴模式）。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Not synchronised to UTC: system_time is time since power-up.</source>
        <translation>未与 UTC 同步：system_time 为上电以来的时间。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>This frame corresponds to a SYNC_OUT pulse.</source>
        <translation>该帧对应一个 SYNC_OUT 脉冲。</translation>
    </message>
</context>
<context>
    <name>imudesk::models::LatestValuesModel</name>
    <message>
        <location filename="../core/models/latest_values_model.cpp" line="+132"/>
        <source>Quantity</source>
        <translation>物理量</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Value</source>
        <translation>数值</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Unit</source>
        <translation>单位</translation>
    </message>
    <message>
        <location line="+71"/>
        <source>none (%1)</source>
        <translation>无 (%1)</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Acceleration %1</source>
        <translation>加速度 %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Angular velocity %1</source>
        <translation>角速度 %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Magnetic field %1</source>
        <translation>磁场 %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Roll</source>
        <translation>横滚角</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Pitch</source>
        <translation>俯仰角</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Yaw</source>
        <translation>航向角</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Quaternion %1</source>
        <translation>四元数 %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Air pressure</source>
        <translation>气压</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Temperature</source>
        <translation>温度</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Device time</source>
        <translation>设备时间</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Status flags</source>
        <translation>状态标志</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Frame type</source>
        <translation>帧类型</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>G</source>
        <translation>G</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>deg/s</source>
        <translation>°/s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>µT</source>
        <translation>µT</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>deg</source>
        <translation>°</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Pa</source>
        <translation>Pa</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>°C</source>
        <translation>°C</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>ms</source>
        <translation>ms</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Acceleration along the sensor&apos;s %1 axis, in G (1 G = 9.8 m/s², the vendor&apos;s constant).</source>
        <translation>沿传感器 %1 轴的加速度，单位 G（1 G = 9.8 m/s²，厂商采用的常数）。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Angular velocity about the sensor&apos;s %1 axis, in deg/s.</source>
        <translation>绕传感器 %1 轴的角速度，单位 °/s。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Magnetic field along the sensor&apos;s %1 axis, in µT.</source>
        <translation>沿传感器 %1 轴的磁场强度，单位 µT。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Roll angle, in degrees (Euler angles in the device&apos;s convention, ENU 312 by default).</source>
        <translation>横滚角，单位 °（设备约定的欧拉角，默认 ENU 312 顺序）。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Pitch angle, in degrees (Euler angles in the device&apos;s convention, ENU 312 by default).</source>
        <translation>俯仰角，单位 °（设备约定的欧拉角，默认 ENU 312 顺序）。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Yaw (heading) angle, in degrees (Euler angles in the device&apos;s convention, ENU 312 by default).</source>
        <translation>航向角，单位 °（设备约定的欧拉角，默认 ENU 312 顺序）。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Attitude quaternion, component %1 (body to navigation frame), no unit.</source>
        <translation>姿态四元数的 %1 分量（载体系到导航系），无单位。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Air pressure from the barometer, in Pa.</source>
        <translation>气压计测得的气压，单位 Pa。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Sensor temperature, in °C.</source>
        <translation>传感器温度，单位 °C。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Device timestamp in ms: UTC time of day when synchronised, otherwise time since power-up.</source>
        <translation>设备时间戳，单位 ms：与 UTC 同步时为当天的 UTC 时间，否则为上电以来的时间。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>MAIN_STATUS flags set in the latest frame (firmware 1.7.0 and later), then the raw word in hex.</source>
        <translation>最新一帧中置位的 MAIN_STATUS 标志（固件 1.7.0 及以上），括号内为十六进制原始值。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The frame type (packet tag) that carried the latest values, e.g. HI91.</source>
        <translation>携带最新数值的帧类型（数据包标签），例如 HI91。</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::ConnectionBar</name>
    <message>
        <location filename="../ui/connection_bar.cpp" line="+148"/>
        <source>SN %1</source>
        <translation>序列号 %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Manufacturer: %1</source>
        <translation>制造商：%1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>USB ID: %1:%2</source>
        <translation>USB ID：%1:%2</translation>
    </message>
    <message>
        <location line="+41"/>
        <source>&amp;Port:</source>
        <translation>串口(&amp;P)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Serial port of the IMU, or a simulated device that runs inside ImuDesk</source>
        <translation>IMU 所连接的串口，或在 ImuDesk 内部运行的模拟设备</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Refresh</source>
        <translation>刷新</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Scan for serial ports again (the list also refreshes every 2 s)</source>
        <translation>重新扫描串口（列表也会每 2 s 自动刷新）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Baud rate:</source>
        <translation>波特率(&amp;B)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Auto</source>
        <translation>自动</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Auto tries every HiPNUC baud rate, starting with 115200</source>
        <translation>自动：从 115200 开始依次尝试 HiPNUC 支持的所有波特率</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Disconnect</source>
        <translation>断开</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Close the connection (Ctrl+D)</source>
        <translation>关闭连接（Ctrl+D）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Connect</source>
        <translation>连接</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Connect to the selected port (Ctrl+K)</source>
        <translation>连接到所选串口（Ctrl+K）</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Simulated %1 (firmware %2)</source>
        <translation>模拟 %1（固件 %2）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 (%2)</source>
        <translation>%1（%2）</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>No serial port found</source>
        <translation>未找到串口</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>A simulated device on a pseudo-terminal, driven exactly like hardware</source>
        <translation>运行在伪终端上的模拟设备，操作方式与真实硬件完全相同</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::ConsoleWidget</name>
    <message>
        <location filename="../ui/console_widget.cpp" line="+71"/>
        <source>(reply to: %1)</source>
        <translation>（对 %1 的应答）</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>ERR: %1</source>
        <translation>错误：%1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Timeout: %1</source>
        <translation>超时：%1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cancelled: %1</source>
        <translation>已取消：%1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Not sent: %1</source>
        <translation>未发送：%1</translation>
    </message>
    <message>
        <location line="+59"/>
        <source>Type an ASCII command, e.g. LOG VERSION, and press Enter</source>
        <translation>输入 ASCII 命令（例如 LOG VERSION）后按回车</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Enter sends the command; Up and Down recall earlier commands</source>
        <translation>回车发送命令；上、下方向键调出历史命令</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Send</source>
        <translation>发送</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Clear log</source>
        <translation>清空日志</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::LanguageSwitcher</name>
    <message>
        <location filename="../ui/language_switcher.cpp" line="+52"/>
        <source>Unknown language &quot;%1&quot;; choose one of: %2.</source>
        <translation>未知语言“%1”；请选择以下之一：%2。</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>The %1 translation was not found in %2.</source>
        <translation>在 %2 中未找到 %1 翻译。</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::MainWindow</name>
    <message>
        <location filename="../ui/main_window.cpp" line="+158"/>
        <source>Disconnect first, then connect to the simulated device.</source>
        <translation>请先断开，再连接模拟设备。</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>The simulated device could not start: %1</source>
        <translation>模拟设备无法启动：%1</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Simulated %1 (firmware %2)</source>
        <translation>模拟 %1（固件 %2）</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>Choose a port first.</source>
        <translation>请先选择串口。</translation>
    </message>
    <message>
        <location line="+48"/>
        <source>ImuDesk</source>
        <translation>ImuDesk</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>About ImuDesk</source>
        <translation>关于 ImuDesk</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&lt;h3&gt;ImuDesk %1&lt;/h3&gt;&lt;p&gt;A bench tool for HiPNUC IMU modules: live values, the ASCII command console and simulated devices.&lt;/p&gt;&lt;p&gt;Built with Qt %2.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;ImuDesk %1&lt;/h3&gt;&lt;p&gt;HiPNUC IMU 模块测试工具：实时数值、ASCII 命令控制台和模拟设备。&lt;/p&gt;&lt;p&gt;基于 Qt %2 构建。&lt;/p&gt;</translation>
    </message>
    <message>
        <location line="+70"/>
        <source>Not connected</source>
        <translation>未连接</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Opening %1…</source>
        <translation>正在打开 %1…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Detecting the baud rate of %1…</source>
        <translation>正在检测 %1 的波特率…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Connected</source>
        <translation>已连接</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Connection to %1 lost</source>
        <translation>与 %1 的连接已断开</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Could not connect to %1</source>
        <translation>无法连接到 %1</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>firmware %1</source>
        <translation>固件 %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>SN %1</source>
        <translation>序列号 %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Product: %1</source>
        <translation>产品：%1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Build: %1</source>
        <translation>构建：%1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Bootloader: %1</source>
        <translation>引导程序：%1</translation>
    </message>
    <message>
        <location line="+8"/>
        <location line="+8"/>
        <source>%1 baud</source>
        <translation>波特率 %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 %2 Hz</source>
        <translation>%1 %2 Hz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no frames</source>
        <translation>无数据帧</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>load %1%</source>
        <translation>负载 %1%</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CRC errors %1</source>
        <translation>CRC 错误 %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>skipped %1 B</source>
        <translation>跳过 %1 B</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Received %1 bytes, %2 frames, %3 NMEA sentences.
Errors: %4 CRC, %5 length, %6 payload, %7 NMEA; %8 bytes skipped.
Link load = bytes per second × 10 bits / baud rate.</source>
        <translation>已接收 %1 字节、%2 帧、%3 条 NMEA 语句。
错误：CRC %4，长度 %5，载荷 %6，NMEA %7；跳过 %8 字节。
链路负载 = 每秒字节数 × 10 位 / 波特率。</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>ImuDesk – IMU bench tool</source>
        <translation>ImuDesk – IMU 测试工具</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 – %2</source>
        <translation>%1 – %2</translation>
    </message>
    <message>
        <location line="+89"/>
        <source>&amp;File</source>
        <translation>文件(&amp;F)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Device</source>
        <translation>设备(&amp;D)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;View</source>
        <translation>视图(&amp;V)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Help</source>
        <translation>帮助(&amp;H)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Quit</source>
        <translation>退出(&amp;Q)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Connect</source>
        <translation>连接(&amp;C)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Connect to the port chosen in the connection bar</source>
        <translation>连接到连接栏中所选的串口</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Disconnect</source>
        <translation>断开(&amp;D)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Send LOG &amp;VERSION</source>
        <translation>发送 LOG &amp;VERSION</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ask the device for its product name, firmware and serial number</source>
        <translation>查询设备的产品型号、固件版本和序列号</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;About ImuDesk</source>
        <translation>关于 ImuDesk(&amp;A)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Console</source>
        <translation>控制台</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Connection</source>
        <translation>连接</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::StatusFlagsWidget</name>
    <message>
        <location filename="../ui/status_flags_widget.cpp" line="+95"/>
        <source>Status:</source>
        <translation>状态：</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>&lt;b&gt;%1&lt;/b&gt; (bit %2): %3</source>
        <translation>&lt;b&gt;%1&lt;/b&gt;（位 %2）：%3</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>MAIN_STATUS flags of the latest frame: green = set, grey = clear, outlined = the frame carries no status word (firmware before 1.7.0, or another frame type)</source>
        <translation>最新一帧的 MAIN_STATUS 标志：绿色 = 置位，灰色 = 未置位，仅边框 = 该帧不含状态字（固件低于 1.7.0 或其他帧类型）</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <location filename="../app/gui/main.cpp" line="+70"/>
        <source>ImuDesk: a bench tool for HiPNUC IMU modules.</source>
        <translation>ImuDesk：HiPNUC IMU 模块测试工具。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>User interface language: zh_CN, zh_TW or en (default: the system&apos;s).</source>
        <translation>界面语言：zh_CN、zh_TW 或 en（默认跟随系统）。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Start connected to a simulated device (model MODEL, default HI14) that streams HI91 at 100 Hz.</source>
        <translation>启动后连接到一个以 100 Hz 输出 HI91 的模拟设备（型号 MODEL，默认 HI14）。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Firmware of the simulated device: 1.7.1 or 1.6.6 (default 1.7.1).</source>
        <translation>模拟设备的固件版本：1.7.1 或 1.6.6（默认 1.7.1）。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Motion of the simulated device: static, spin or tumble (default static).</source>
        <translation>模拟设备的运动方式：static（静止）、spin（旋转）或 tumble（翻滚）（默认 static）。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Start connected to this serial port.</source>
        <translation>启动后连接到此串口。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Baud rate for --port or --simulate (default: detect automatically).</source>
        <translation>--port 或 --simulate 使用的波特率（默认自动检测）。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Model to simulate with --simulate (default HI14).</source>
        <translation>--simulate 模拟的型号（默认 HI14）。</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>A model name is only accepted after --simulate.</source>
        <translation>型号名称只能跟在 --simulate 之后。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Use either --simulate or --port, not both.</source>
        <translation>--simulate 和 --port 只能二选一。</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Unsupported baud rate &quot;%1&quot;; use auto or one of: %2.</source>
        <translation>不支持的波特率“%1”；请使用 auto 或以下之一：%2。</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Invalid firmware version &quot;%1&quot;; use e.g. 1.7.1 or 1.6.6.</source>
        <translation>无效的固件版本“%1”；请使用例如 1.7.1 或 1.6.6。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Unknown motion &quot;%1&quot;; use static, spin or tumble.</source>
        <translation>未知的运动方式“%1”；请使用 static、spin 或 tumble。</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>ImuDesk</source>
        <translation>ImuDesk</translation>
    </message>
</context>
</TS>
