<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="zh_CN">
<context>
    <name>PtySimulator</name>
    <message>
        <location filename="../core/sim/pty_simulator.cpp" line="+251" />
        <source>Cannot open a pseudo-terminal: %1</source>
        <translation>无法打开伪终端：%1</translation>
    </message>
</context>
<context>
    <name>imudesk::device::SessionWorker</name>
    <message>
        <location filename="../core/device/session_worker.cpp" line="+123" />
        <source>the connection was closed</source>
        <translation>连接已关闭</translation>
    </message>
    <message>
        <location line="+27" />
        <source>automatic reconnection was turned off</source>
        <translation>自动重连已关闭</translation>
    </message>
    <message>
        <location line="+19" />
        <source>the port is not open</source>
        <translation>串口未打开</translation>
    </message>
    <message>
        <location line="+26" />
        <source>writing to the port failed</source>
        <translation>向串口写入失败</translation>
    </message>
    <message>
        <location line="+29" />
        <source>no reply within %1 ms (the device ignores commands it does not know)</source>
        <translation>%1 ms 内无应答（设备不响应它不认识的指令）</translation>
    </message>
    <message>
        <location line="+163" />
        <source>The device that came back on %1 is a different one (serial %2, before %3). Its data continues in this session.</source>
        <translation>%1 上重新出现的是另一台设备（序列号 %2，之前为 %3）。其数据将继续记录在本会话中。</translation>
    </message>
    <message>
        <location line="+13" />
        <source>disconnected — waiting for the device to come back</source>
        <translation>已断开，正在等待设备重新连接</translation>
    </message>
    <message>
        <location line="+33" />
        <source>%1 at %2 baud (reconnected)</source>
        <translation>%1，波特率 %2（已重连）</translation>
    </message>
    <message>
        <location line="+143" />
        <source>Bytes keep arriving on %1 but none of them form a frame: the device probably runs at another baud rate now. Disconnect and connect again with the baud rate set to Auto.</source>
        <translation>%1 上持续收到字节，但无法组成任何数据帧：设备可能已改用其他波特率。请断开连接，并将波特率设为“自动”后重新连接。</translation>
    </message>
    <message>
        <location line="+61" />
        <source>No HiPNUC device answered on %1 at any baud rate (115200, 921600, 460800, 230400, 256000, 57600, 38400, 19200, 9600, 4800). Check the cable and the power, and that no other program uses the port.</source>
        <translation>%1 上在所有波特率（115200、921600、460800、230400、256000、57600、38400、19200、9600、4800）下都没有 HiPNUC 设备应答。请检查线缆和电源，并确认没有其他程序占用该串口。</translation>
    </message>
    <message>
        <location line="+15" />
        <source>trying %1 baud</source>
        <translation>正在尝试 %1 波特率</translation>
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
        <translation>未找到串口 %1。请检查设备是否已插好，然后从列表中重新选择串口。</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Port %1 is in use by another program (a serial terminal, CHCenter or another ImuDesk). Close that program and connect again.</source>
        <translation>串口 %1 正被其他程序占用（串口终端、CHCenter 或另一个 ImuDesk）。请关闭该程序后重新连接。</translation>
    </message>
    <message>
        <location line="+5" />
        <source>No permission to open %1. On Linux add your user to the dialout group (sudo usermod -aG dialout $USER), then log out and in again.</source>
        <translation>没有打开 %1 的权限。在 Linux 上请将当前用户加入 dialout 组（sudo usermod -aG dialout $USER），然后注销并重新登录。</translation>
    </message>
    <message>
        <location line="+8" />
        <source>Could not open %1: %2</source>
        <translation>无法打开 %1：%2</translation>
    </message>
    <message>
        <location line="+129" />
        <source>The connection to %1 was lost (%2). Check the cable; everything received so far is kept.</source>
        <translation>与 %1 的连接已断开（%2）。请检查线缆；已接收的数据都会保留。</translation>
    </message>
</context>
<context>
    <name>imudesk::model::MainStatus</name>
    <message>
        <location filename="../core/model/main_status.cpp" line="+11" />
        <source>Gyro bias estimate not yet converged: keep the module still for 3-5 s to improve heading accuracy.</source>
        <translation>陀螺零偏估计尚未收敛：请保持模块静止 3-5 s，以提高航向角精度。</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Magnetic disturbance: the field is disturbed, the magnetometer is not calibrated or the hard-iron environment changed; 9-axis heading may be wrong.</source>
        <translation>磁场干扰：磁场受到干扰、磁力计未校准或硬磁环境发生变化；9 轴航向角可能不准确。</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Accelerometer over range now or within the last 2 s.</source>
        <translation>加速度计当前或最近 2 s 内超量程。</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Gyroscope over range now or within the last 2 s.</source>
        <translation>陀螺仪当前或最近 2 s 内超量程。</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Attitude accuracy poor (large AHRS filter covariance): keep still for a moment.</source>
        <translation>姿态精度差（AHRS 滤波器协方差较大）：请保持静止片刻。</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The device detected that it is static.</source>
        <translation>设备检测到自身处于静止状态。</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The magnetometer takes part in heading (9-axis mode).</source>
        <translation>磁力计参与航向解算（9 轴模式）。</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Not synchronised to UTC: system_time is time since power-up.</source>
        <translation>未与 UTC 同步：system_time 为上电以来的时间。</translation>
    </message>
    <message>
        <location line="+1" />
        <source>This frame corresponds to a SYNC_OUT pulse.</source>
        <translation>该帧对应一个 SYNC_OUT 脉冲。</translation>
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
        <translation>超时</translation>
    </message>
    <message>
        <location line="+1" />
        <source>cancelled</source>
        <translation>已取消</translation>
    </message>
    <message>
        <location line="+1" />
        <source>not sent</source>
        <translation>未发送</translation>
    </message>
    <message>
        <location line="+50" />
        <source>Time</source>
        <translation>时间</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Command</source>
        <translation>指令</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Status</source>
        <translation>状态</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Reply</source>
        <translation>应答</translation>
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
        <translation>数值</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Unit</source>
        <translation>单位</translation>
    </message>
    <message>
        <location line="+82" />
        <source>0 invalid</source>
        <translation>0 解无效</translation>
    </message>
    <message>
        <location line="+1" />
        <source>1 aligning</source>
        <translation>1 对准中</translation>
    </message>
    <message>
        <location line="+1" />
        <source>3 navigating</source>
        <translation>3 组合导航中</translation>
    </message>
    <message>
        <location line="+1" />
        <source>6 dead reckoning</source>
        <translation>6 惯性递推中</translation>
    </message>
    <message>
        <location line="+23" />
        <source>none (%1)</source>
        <translation>无 (%1)</translation>
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
        <translation>磁场 %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Roll</source>
        <translation>横滚角</translation>
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
        <translation>四元数 %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Air pressure</source>
        <translation>气压</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Temperature</source>
        <translation>温度</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Device time</source>
        <translation>设备时间</translation>
    </message>
    <message>
        <location line="+1" />
        <source>INS status</source>
        <translation>组合导航状态</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Latitude</source>
        <translation>纬度</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Longitude</source>
        <translation>经度</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Altitude (MSL)</source>
        <translation>海拔高度</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Velocity east</source>
        <translation>东向速度</translation>
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
        <translation>垂荡</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Surge</source>
        <translation>纵荡</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Sway</source>
        <translation>横荡</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Inclination X</source>
        <translation>X 轴倾角</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Inclination Y</source>
        <translation>Y 轴倾角</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Status flags</source>
        <translation>状态标志</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Frame type</source>
        <translation>帧类型</translation>
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
        <translation>沿传感器 %1 轴的加速度，单位 G（1 G = 9.8 m/s²，厂商采用的常数）。</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Angular velocity about the sensor's %1 axis, in deg/s.</source>
        <translation>绕传感器 %1 轴的角速度，单位 °/s。</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Magnetic field along the sensor's %1 axis, in µT.</source>
        <translation>沿传感器 %1 轴的磁场强度，单位 µT。</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Roll angle, in degrees (Euler angles in the device's convention, ENU 312 by default).</source>
        <translation>横滚角，单位 °（设备约定的欧拉角，默认 ENU 312 顺序）。</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Pitch angle, in degrees (Euler angles in the device's convention, ENU 312 by default).</source>
        <translation>俯仰角，单位 °（设备约定的欧拉角，默认 ENU 312 顺序）。</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Yaw (heading) angle, in degrees (Euler angles in the device's convention, ENU 312 by default).</source>
        <translation>航向角，单位 °（设备约定的欧拉角，默认 ENU 312 顺序）。</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Attitude quaternion, component %1 (body to navigation frame), no unit.</source>
        <translation>姿态四元数的 %1 分量（载体系到导航系），无单位。</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Air pressure from the barometer, in Pa.</source>
        <translation>气压计测得的气压，单位 Pa。</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Sensor temperature, in °C.</source>
        <translation>传感器温度，单位 °C。</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Device timestamp in ms: UTC time of day when synchronised, otherwise time since power-up.</source>
        <translation>设备时间戳，单位 ms：与 UTC 同步时为当天的 UTC 时间，否则为上电以来的时间。</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Integrated navigation state: 0 invalid, 1 aligning, 3 navigating, 6 dead reckoning.</source>
        <translation>组合导航解状态：0 解无效，1 对准中，3 组合导航中，6 惯性递推中。</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Position from integrated navigation, in degrees (south and west negative).</source>
        <translation>组合导航解算的位置，单位 °（南纬和西经为负）。</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Height above mean sea level, in m.</source>
        <translation>平均海平面以上的高度，单位 m。</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Velocity in the east-north-up frame, in m/s.</source>
        <translation>东北天（ENU）坐标系下的速度，单位 m/s。</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Ship motion displacement (heave, surge, sway), in m.</source>
        <translation>船舶运动位移（垂荡、纵荡、横荡），单位 m。</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Inclinometer angle about the %1 axis, in degrees.</source>
        <translation>倾角仪绕 %1 轴的角度，单位 °。</translation>
    </message>
    <message>
        <location line="+2" />
        <source>MAIN_STATUS flags set in the latest frame (firmware 1.7.0 and later), then the raw word in hex.</source>
        <translation>最新一帧中置位的 MAIN_STATUS 标志（固件 1.7.0 及以上），括号内为十六进制原始值。</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The frame type (packet tag) that carried the latest values, e.g. HI91.</source>
        <translation>携带最新数值的帧类型（数据包标签），例如 HI91。</translation>
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
        <translation>尚无姿态数据</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Roll</source>
        <translation>横滚角</translation>
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
        <translation>拖动以旋转视图，双击以复位</translation>
    </message>
    <message>
        <location line="+351" />
        <source>Reset view</source>
        <translation>复位视图</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::ChartPanel</name>
    <message>
        <location filename="../ui/chart_panel.cpp" line="+66" />
        <source>&amp;Time axis:</source>
        <translation>时间轴(&amp;T)：</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Device clock</source>
        <translation>设备时钟</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Host arrival time</source>
        <translation>主机接收时间</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Device clock: the module's own timestamps, where lost samples show as gaps. Host arrival time: when the samples reached this computer.</source>
        <translation>设备时钟：模块自身的时间戳，丢失的采样显示为间断。主机接收时间：采样到达本计算机的时间。</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::ChartView</name>
    <message>
        <location filename="../ui/chart_view.cpp" line="+107" />
        <source>Accelerometer</source>
        <translation>加速度计</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Gyroscope</source>
        <translation>陀螺仪</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Magnetometer</source>
        <translation>磁力计</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Euler angles</source>
        <translation>欧拉角</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Quaternion</source>
        <translation>四元数</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Air pressure</source>
        <translation>气压</translation>
    </message>
    <message>
        <location line="+1" />
        <location line="+14" />
        <location line="+39" />
        <source>Temperature</source>
        <translation>温度</translation>
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
        <translation>磁场</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Angle</source>
        <translation>角度</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Quaternion component</source>
        <translation>四元数分量</translation>
    </message>
    <message>
        <location line="+1" />
        <location line="+39" />
        <source>Pressure</source>
        <translation>气压</translation>
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
        <translation>横滚角</translation>
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
        <translation>磁场 %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Quaternion %1</source>
        <translation>四元数 %1</translation>
    </message>
    <message>
        <location line="+40" />
        <source>Device time (s)</source>
        <translation>设备时间（s）</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Host arrival time (s)</source>
        <translation>主机接收时间（s）</translation>
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
        <translation>无法绘制图表</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Could not save the chart as %1: %2</source>
        <translation>无法将图表保存为 %1：%2</translation>
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
        <translation>显示或隐藏 %1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>&amp;Window:</source>
        <translation>时间窗(&amp;W)：</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Time span shown by this chart</source>
        <translation>此图表显示的时间跨度</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Auto scale</source>
        <translation>自动缩放</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Fit the vertical axis to the data shown; off: use the range on the right</source>
        <translation>使纵轴适应所显示的数据；关闭时使用右侧设定的范围</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Lower end of the vertical axis (no unit)</source>
        <translation>纵轴下限（无单位）</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Upper end of the vertical axis (no unit)</source>
        <translation>纵轴上限（无单位）</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Lower end of the vertical axis, in %1</source>
        <translation>纵轴下限，单位 %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Upper end of the vertical axis, in %1</source>
        <translation>纵轴上限，单位 %1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Save as PNG…</source>
        <translation>另存为 PNG…</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Save this chart as a PNG image</source>
        <translation>将此图表保存为 PNG 图像</translation>
    </message>
    <message>
        <location line="+9" />
        <source>Resume</source>
        <translation>继续</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Pause</source>
        <translation>暂停</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Follow the newest data again</source>
        <translation>重新跟随最新数据</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Freeze this chart; the data keeps being recorded</source>
        <translation>冻结此图表；数据仍会继续记录</translation>
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
        <translation>将图表保存为 PNG</translation>
    </message>
    <message>
        <location line="-7" />
        <source>PNG images (*.png)</source>
        <translation>PNG 图像 (*.png)</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::CommandLogWidget</name>
    <message>
        <location filename="../ui/command_log_widget.cpp" line="+169" />
        <source>Copy</source>
        <translation>复制</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Copy the selected commands as tab-separated text</source>
        <translation>将所选指令复制为制表符分隔的文本</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Copy all</source>
        <translation>全部复制</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Copy every command as tab-separated text</source>
        <translation>将所有指令复制为制表符分隔的文本</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Clear</source>
        <translation>清空</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Remove every command from the list</source>
        <translation>从列表中移除所有指令</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::ComparisonChart</name>
    <message>
        <location filename="../ui/comparison_chart.cpp" line="+113" />
        <source>Comparison</source>
        <translation>对比</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Channel:</source>
        <translation>通道(&amp;C)：</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The quantity compared across the devices</source>
        <translation>在各设备之间对比的物理量</translation>
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
        <translation>时间窗(&amp;W)：</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Time span shown</source>
        <translation>显示的时间跨度</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Save as PNG…</source>
        <translation>另存为 PNG…</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Save this chart as a PNG image</source>
        <translation>将此图表保存为 PNG 图像</translation>
    </message>
    <message>
        <location line="+17" />
        <source>Resume</source>
        <translation>继续</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Pause</source>
        <translation>暂停</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Follow the newest data again</source>
        <translation>重新跟随最新数据</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Freeze this chart; the data keeps being recorded</source>
        <translation>冻结此图表；数据仍会继续记录</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::ConnectionBar</name>
    <message>
        <location filename="../ui/connection_bar.cpp" line="+148" />
        <source>SN %1</source>
        <translation>序列号 %1</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Manufacturer: %1</source>
        <translation>制造商：%1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>USB ID: %1:%2</source>
        <translation>USB ID：%1:%2</translation>
    </message>
    <message>
        <location line="+41" />
        <source>&amp;Port:</source>
        <translation>串口(&amp;P)：</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Serial port of the IMU, or a simulated device that runs inside ImuDesk</source>
        <translation>IMU 所连接的串口，或在 ImuDesk 内部运行的模拟设备</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Refresh</source>
        <translation>刷新</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Scan for serial ports again (the list also refreshes every 2 s)</source>
        <translation>重新扫描串口（列表也会每 2 s 自动刷新）</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Baud rate:</source>
        <translation>波特率(&amp;B)：</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Auto</source>
        <translation>自动</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Auto tries every HiPNUC baud rate, starting with 115200</source>
        <translation>自动：从 115200 开始依次尝试 HiPNUC 支持的所有波特率</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Disconnect</source>
        <translation>断开</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Close the connection (Ctrl+D)</source>
        <translation>关闭连接（Ctrl+D）</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Connect</source>
        <translation>连接</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Connect to the selected port (Ctrl+K)</source>
        <translation>连接到所选串口（Ctrl+K）</translation>
    </message>
    <message>
        <location line="+7" />
        <source>Simulated %1 (firmware %2)</source>
        <translation>模拟 %1（固件 %2）</translation>
    </message>
    <message>
        <location line="+4" />
        <source>%1 (%2)</source>
        <translation>%1（%2）</translation>
    </message>
    <message>
        <location line="+25" />
        <source>No serial port found</source>
        <translation>未找到串口</translation>
    </message>
    <message>
        <location line="+5" />
        <source>A simulated device on a pseudo-terminal, driven exactly like hardware</source>
        <translation>运行在伪终端上的模拟设备，操作方式与真实硬件完全相同</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::ConsoleWidget</name>
    <message>
        <location filename="../ui/console_widget.cpp" line="+127" />
        <source>(reply to: %1)</source>
        <translation>（对 %1 的应答）</translation>
    </message>
    <message>
        <location line="+7" />
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <location line="+1" />
        <source>ERR: %1</source>
        <translation>错误：%1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Timeout: %1</source>
        <translation>超时：%1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Cancelled: %1</source>
        <translation>已取消：%1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Not sent: %1</source>
        <translation>未发送：%1</translation>
    </message>
    <message>
        <location line="+59" />
        <source>Type an ASCII command, e.g. LOG VERSION, and press Enter</source>
        <translation>输入 ASCII 指令（例如 LOG VERSION）后按回车</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Enter sends the command; Up and Down recall earlier commands</source>
        <translation>回车发送指令；上、下方向键调出历史指令</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Send</source>
        <translation>发送</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Clear log</source>
        <translation>清空日志</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::DeviceWorkspace</name>
    <message>
        <location filename="../ui/device_workspace.cpp" line="+212" />
        <source>New connection</source>
        <translation>新连接</translation>
    </message>
    <message>
        <location line="+2" />
        <source>%1 on %2</source>
        <translation>%2 上的 %1</translation>
    </message>
    <message>
        <location line="+42" />
        <source>Disconnect first, then connect to the simulated device.</source>
        <translation>请先断开，再连接模拟设备。</translation>
    </message>
    <message>
        <location line="+9" />
        <source>The simulated device could not start: %1</source>
        <translation>模拟设备无法启动：%1</translation>
    </message>
    <message>
        <location line="+8" />
        <source>Simulated %1 (firmware %2)</source>
        <translation>模拟 %1（固件 %2）</translation>
    </message>
    <message>
        <location line="+129" />
        <source>Not connected</source>
        <translation>未连接</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Opening %1…</source>
        <translation>正在打开 %1…</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Detecting the baud rate of %1…</source>
        <translation>正在检测 %1 的波特率…</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Connected</source>
        <translation>已连接</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Connection to %1 lost</source>
        <translation>与 %1 的连接已断开</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Disconnected from %1 — waiting for the device to come back</source>
        <translation>已与 %1 断开，正在等待设备重新连接</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Could not connect to %1</source>
        <translation>无法连接到 %1</translation>
    </message>
    <message>
        <location line="+13" />
        <source>firmware %1</source>
        <translation>固件 %1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>SN %1</source>
        <translation>序列号 %1</translation>
    </message>
    <message>
        <location line="+6" />
        <source>Product: %1</source>
        <translation>产品：%1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Build: %1</source>
        <translation>构建：%1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Bootloader: %1</source>
        <translation>引导程序：%1</translation>
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
        <translation>无数据帧</translation>
    </message>
    <message>
        <location line="+1" />
        <source>load %1%</source>
        <translation>负载 %1%</translation>
    </message>
    <message>
        <location line="+1" />
        <source>CRC errors %1</source>
        <translation>CRC 错误 %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>lost %1</source>
        <translation>丢失 %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>skipped %1 B</source>
        <translation>跳过 %1 B</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Received %1 bytes, %2 frames, %3 NMEA sentences.
Errors: %4 CRC, %5 length, %6 payload, %7 NMEA; %8 bytes skipped.
Frames lost (gaps in the device time): %9.
Link load = bytes per second × 10 bits / baud rate.</source>
        <translation>已接收 %1 字节、%2 帧、%3 条 NMEA 语句。
错误：CRC %4 个，长度 %5 个，载荷 %6 个，NMEA %7 个；跳过 %8 字节。
丢失的帧（设备时间中的间断）：%9。
链路负载 = 每秒字节数 × 10 位 / 波特率。</translation>
    </message>
    <message>
        <location line="+48" />
        <source>Console</source>
        <translation>控制台</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Raw bytes</source>
        <translation>原始字节</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Command log</source>
        <translation>指令日志</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Values and attitude</source>
        <translation>数值与姿态</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::LanguageSwitcher</name>
    <message>
        <location filename="../ui/language_switcher.cpp" line="+52" />
        <source>Unknown language "%1"; choose one of: %2.</source>
        <translation>未知语言“%1”；请选择以下之一：%2。</translation>
    </message>
    <message>
        <location line="+14" />
        <source>The %1 translation was not found in %2.</source>
        <translation>在 %2 中未找到 %1 翻译。</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::MainWindow</name>
    <message>
        <location filename="../ui/main_window.cpp" line="+239" />
        <source>Choose a port first.</source>
        <translation>请先选择串口。</translation>
    </message>
    <message>
        <location line="+50" />
        <source>Could not save the screenshot to %1: %2</source>
        <translation>无法将截图保存到 %1：%2</translation>
    </message>
    <message>
        <location line="+19" />
        <source>ImuDesk</source>
        <translation>ImuDesk</translation>
    </message>
    <message>
        <location line="+9" />
        <source>About ImuDesk</source>
        <translation>关于 ImuDesk</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&lt;h3&gt;ImuDesk %1&lt;/h3&gt;&lt;p&gt;A bench tool for HiPNUC IMU modules: live values, the ASCII command console and simulated devices.&lt;/p&gt;&lt;p&gt;Built with Qt %2.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;ImuDesk %1&lt;/h3&gt;&lt;p&gt;HiPNUC IMU 模块测试工具：实时数值、ASCII 指令控制台和模拟设备。&lt;/p&gt;&lt;p&gt;基于 Qt %2 构建。&lt;/p&gt;</translation>
    </message>
    <message>
        <location line="+18" />
        <source>ImuDesk – IMU bench tool</source>
        <translation>ImuDesk – IMU 测试工具</translation>
    </message>
    <message>
        <location line="+3" />
        <source>%1 – %2</source>
        <translation>%1 – %2</translation>
    </message>
    <message>
        <location line="+48" />
        <source>Save screenshot</source>
        <translation>保存截图</translation>
    </message>
    <message>
        <location line="+1" />
        <source>PNG images (*.png)</source>
        <translation>PNG 图像 (*.png)</translation>
    </message>
    <message>
        <location line="+60" />
        <source>&amp;File</source>
        <translation>文件(&amp;F)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Device</source>
        <translation>设备(&amp;D)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;View</source>
        <translation>视图(&amp;V)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Help</source>
        <translation>帮助(&amp;H)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;New connection tab</source>
        <translation>新建连接标签页(&amp;N)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Open a tab for another device; each tab has its own connection and views</source>
        <translation>为另一台设备打开一个标签页；每个标签页都有独立的连接和视图</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Close tab</source>
        <translation>关闭标签页(&amp;C)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Save &amp;screenshot…</source>
        <translation>保存截图(&amp;S)…</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Quit</source>
        <translation>退出(&amp;Q)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Connect</source>
        <translation>连接(&amp;C)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Connect to the port chosen in the connection bar</source>
        <translation>连接到连接栏中所选的串口</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Disconnect</source>
        <translation>断开(&amp;D)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Send LOG &amp;VERSION</source>
        <translation>发送 LOG &amp;VERSION</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Ask the device for its product name, firmware and serial number</source>
        <translation>查询设备的产品型号、固件版本和序列号</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;About ImuDesk</source>
        <translation>关于 ImuDesk(&amp;A)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Preferences…</source>
        <translation>首选项(&amp;P)…</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Compare devices</source>
        <translation>设备对比</translation>
    </message>
    <message>
        <location line="-1" />
        <source>Connection</source>
        <translation>连接</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::PreferencesDialog</name>
    <message>
        <location filename="../ui/preferences_dialog.cpp" line="+21" />
        <source>Preferences</source>
        <translation>首选项</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Language</source>
        <translation>语言</translation>
    </message>
    <message>
        <location line="+3" />
        <source>System language</source>
        <translation>跟随系统</translation>
    </message>
    <message>
        <location line="+4" />
        <source>The language of the user interface. Takes effect the next time ImuDesk starts.</source>
        <translation>用户界面的语言。下次启动 ImuDesk 时生效。</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Language:</source>
        <translation>语言(&amp;L)：</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The new language is used after a restart.</source>
        <translation>新语言在重新启动后生效。</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Display</source>
        <translation>显示</translation>
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
        <translation>加速度计数值和曲线的单位。记录的数据保持设备的单位（G）。</translation>
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
        <translation>陀螺仪数值和曲线的单位。记录的数据保持设备的单位（deg/s）。</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Angular &amp;rate:</source>
        <translation>角速度(&amp;R)：</translation>
    </message>
    <message>
        <location line="+2" />
        <source>ENU (east, north, up)</source>
        <translation>ENU（东、北、天）</translation>
    </message>
    <message>
        <location line="+1" />
        <source>NED (north, east, down)</source>
        <translation>NED（北、东、地）</translation>
    </message>
    <message>
        <location line="+1" />
        <source>World frame of the 3D attitude view.</source>
        <translation>三维姿态视图的世界坐标系。</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Attitude &amp;frame:</source>
        <translation>姿态坐标系(&amp;F)：</translation>
    </message>
    <message>
        <location line="+3" />
        <source> Hz</source>
        <translation> Hz</translation>
    </message>
    <message>
        <location line="+1" />
        <source>How often charts and values are redrawn (%1 to %2 Hz). Lower rates use less CPU.</source>
        <translation>曲线和数值的刷新频率（%1 至 %2 Hz）。频率越低占用 CPU 越少。</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Chart &amp;refresh:</source>
        <translation>曲线刷新(&amp;R)：</translation>
    </message>
    <message>
        <location line="+3" />
        <source> min</source>
        <translation> 分钟</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The longest time window a chart can show (%1 to %2 minutes).</source>
        <translation>曲线可显示的最长时间窗口（%1 至 %2 分钟）。</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Chart &amp;history:</source>
        <translation>曲线历史(&amp;H)：</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Recording</source>
        <translation>记录</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Documents folder</source>
        <translation>文档文件夹</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Where new recordings are written.</source>
        <translation>新记录保存的位置。</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Browse…</source>
        <translation>浏览(&amp;B)…</translation>
    </message>
    <message>
        <location line="+4" />
        <source>&amp;Folder:</source>
        <translation>文件夹(&amp;F)：</translation>
    </message>
    <message>
        <location line="+2" />
        <source>File name of a new recording. {device}, {serial}, {date} and {time} are replaced.</source>
        <translation>新记录的文件名。{device}、{serial}、{date} 和 {time} 会被替换。</translation>
    </message>
    <message>
        <location line="+1" />
        <source>File &amp;pattern:</source>
        <translation>文件名模式(&amp;P)：</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Example:</source>
        <translation>示例：</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Connection</source>
        <translation>连接</translation>
    </message>
    <message>
        <location line="+2" />
        <source>&amp;Reconnect by itself when an unplugged device comes back</source>
        <translation>拔出的设备重新插入时自动重连(&amp;R)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>After a cable is pulled, wait for the same device (USB serial number, else port) and reconnect at the last baud rate.</source>
        <translation>线缆拔出后，等待同一设备（按 USB 序列号，否则按端口）重新出现，并以上次的波特率重新连接。</translation>
    </message>
    <message>
        <location line="+59" />
        <source>Recording folder</source>
        <translation>记录文件夹</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::RawBytesView</name>
    <message numerus="yes">
        <location filename="../ui/raw_bytes_view.cpp" line="+196" />
        <source>… %n read(s) or write(s) not shown (the log dropped them before this view caught up) …</source>
        <translation>
            <numerusform>… 有 %n 次读取或写入未显示（在此视图跟上之前，日志已将其丢弃）…</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+3" />
        <source>… %n byte(s) not shown (more arrived than the view holds) …</source>
        <translation>
            <numerusform>… 有 %n 字节未显示（到达的数据超出视图容量）…</numerusform>
        </translation>
    </message>
    <message>
        <location line="+64" />
        <source>Pause</source>
        <translation>暂停</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Stop updating the view; the bytes are still recorded</source>
        <translation>停止更新视图；字节仍会继续记录</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Clear</source>
        <translation>清空</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Empty the view</source>
        <translation>清空视图</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Copy</source>
        <translation>复制</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Copy the selected lines, or everything shown, to the clipboard</source>
        <translation>将所选行（未选择时为全部显示内容）复制到剪贴板</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Link traffic: time (s), direction (RX from the device, TX to it), byte offset, hex and ASCII</source>
        <translation>链路流量：时间（s）、方向（RX 为来自设备，TX 为发往设备）、字节偏移、十六进制和 ASCII</translation>
    </message>
    <message>
        <location line="+7" />
        <source>RX %1 bytes, TX %2 bytes</source>
        <translation>RX %1 字节，TX %2 字节</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Paused — %1</source>
        <translation>已暂停 — %1</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::StatusFlagsWidget</name>
    <message>
        <location filename="../ui/status_flags_widget.cpp" line="+95" />
        <source>Status:</source>
        <translation>状态：</translation>
    </message>
    <message>
        <location line="+6" />
        <source>&lt;b&gt;%1&lt;/b&gt; (bit %2): %3</source>
        <translation>&lt;b&gt;%1&lt;/b&gt;（位 %2）：%3</translation>
    </message>
    <message>
        <location line="+2" />
        <source>MAIN_STATUS flags of the latest frame: green = set, grey = clear, outlined = the frame carries no status word (firmware before 1.7.0, or another frame type)</source>
        <translation>最新一帧的 MAIN_STATUS 标志：绿色 = 置位，灰色 = 未置位，仅边框 = 该帧不含状态字（固件低于 1.7.0 或其他帧类型）</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <location filename="../app/gui/main.cpp" line="+82" />
        <source>ImuDesk: a bench tool for HiPNUC IMU modules.</source>
        <translation>ImuDesk：HiPNUC IMU 模块测试工具。</translation>
    </message>
    <message>
        <location line="+5" />
        <source>User interface language: zh_CN, zh_TW or en (default: the system's).</source>
        <translation>界面语言：zh_CN、zh_TW 或 en（默认跟随系统）。</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Start connected to a simulated device (model MODEL, default HI14) that streams HI91 at 100 Hz.</source>
        <translation>启动后连接到一个以 100 Hz 输出 HI91 的模拟设备（型号 MODEL，默认 HI14）。</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Firmware of the simulated device: 1.7.1 or 1.6.6 (default 1.7.1).</source>
        <translation>模拟设备的固件版本：1.7.1 或 1.6.6（默认 1.7.1）。</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Motion of the simulated device: static, spin or tumble (default static).</source>
        <translation>模拟设备的运动方式：static（静止）、spin（旋转）或 tumble（翻滚）（默认 static）。</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Start connected to this serial port.</source>
        <translation>启动后连接到此串口。</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Baud rate for --port or --simulate (default: detect automatically).</source>
        <translation>--port 或 --simulate 使用的波特率（默认自动检测）。</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Start connected to a simulated HI14 (firmware 1.7.1) that tumbles slowly through every orientation.</source>
        <translation>启动后连接到一个模拟 HI14（固件 1.7.1），它会缓慢翻滚，经历所有姿态。</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Save the main window to this PNG file and quit (see --after).</source>
        <translation>将主窗口保存为此 PNG 文件后退出（参见 --after）。</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Seconds to wait before --screenshot (default 3).</source>
        <translation>执行 --screenshot 前等待的秒数（默认 3）。</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Model to simulate with --simulate (default HI14).</source>
        <translation>--simulate 模拟的型号（默认 HI14）。</translation>
    </message>
    <message>
        <location line="+8" />
        <source>A model name is only accepted after --simulate.</source>
        <translation>型号名称只能跟在 --simulate 之后。</translation>
    </message>
    <message>
        <location line="+6" />
        <source>--after needs a number of seconds from 0 to 3600.</source>
        <translation>--after 需要 0 到 3600 之间的秒数。</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Use either --simulate or --port, not both.</source>
        <translation>--simulate 和 --port 只能二选一。</translation>
    </message>
    <message>
        <location line="+11" />
        <source>Unsupported baud rate "%1"; use auto or one of: %2.</source>
        <translation>不支持的波特率“%1”；请使用 auto 或以下之一：%2。</translation>
    </message>
    <message>
        <location line="+9" />
        <source>Invalid firmware version "%1"; use e.g. 1.7.1 or 1.6.6.</source>
        <translation>无效的固件版本“%1”；请使用例如 1.7.1 或 1.6.6。</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Unknown motion "%1"; use static, spin or tumble.</source>
        <translation>未知的运动方式“%1”；请使用 static、spin 或 tumble。</translation>
    </message>
    <message>
        <location line="+20" />
        <source>ImuDesk</source>
        <translation>ImuDesk</translation>
    </message>
</context>
</TS>