<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="zh_CN">
<context>
    <name>BandwidthCalculator</name>
    <message>
        <location filename="../core/settings/bandwidth_calculator.cpp" line="+70"/>
        <source>The output needs %1 bytes/s but %2 baud carries only %3 bytes/s (%4 %): frames will be lost. %5</source>
        <translation>输出需要 %1 字节/秒，但波特率 %2 只能传输 %3 字节/秒（%4 %）：将会丢帧。%5</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Raise the baud rate to %1 or lower the rates.</source>
        <translation>请将波特率提高到 %1，或降低输出频率。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Lower the rates or turn some messages off.</source>
        <translation>请降低输出频率，或关闭部分输出消息。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The output uses %1 % of the link at %2 baud: little margin left, a higher baud rate is safer.</source>
        <translation>波特率 %2 下，输出占用链路的 %1 %：余量很小，使用更高的波特率更稳妥。</translation>
    </message>
</context>
<context>
    <name>CalibrationHistory</name>
    <message>
        <location filename="../core/calib/calibration_history.cpp" line="+82"/>
        <source>A calibration record needs a kind.</source>
        <translation>校准记录必须指定类型。</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Cannot create the folder %1: check that the disk is writable.</source>
        <translation>无法创建文件夹 %1：请检查磁盘是否可写。</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+3"/>
        <location line="+3"/>
        <location line="+3"/>
        <source>Cannot write %1: %2</source>
        <translation>无法写入 %1：%2</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>%1 is too large to load.</source>
        <translation>%1 太大，无法加载。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Cannot read %1: %2</source>
        <translation>无法读取 %1：%2</translation>
    </message>
</context>
<context>
    <name>CalibrationReport</name>
    <message>
        <location filename="../ui/calibration/calibration_report.cpp" line="+36"/>
        <source>Fit</source>
        <translation>拟合方式</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Soft-iron matrix (rows, unitless)</source>
        <translation>软磁矩阵（按行，无单位）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Fit error (%)</source>
        <translation>拟合误差（%）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Sphere coverage (%)</source>
        <translation>球面覆盖率（%）</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Soft-iron uncertainty, RMS (%)</source>
        <translation>软磁不确定度，RMS (%)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Eigenvalue ratio (max/min)</source>
        <translation>特征值比（最大/最小）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Samples fitted</source>
        <translation>参与拟合的样本数</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Samples set aside as outliers</source>
        <translation>剔除为离群值的样本数</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Hard-iron-only fit offered</source>
        <translation>提供仅硬磁拟合</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Planar (2-D) fit offered</source>
        <translation>提供平面（二维）拟合</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Vertical offset known</source>
        <translation>竖直方向偏移已知</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Target angle (deg)</source>
        <translation>目标角度（deg）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Device accepted</source>
        <translation>设备已接受</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Device reply</source>
        <translation>设备应答</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>ImuDesk estimate available</source>
        <translation>已有 ImuDesk 估计值</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Scale error, ImuDesk estimate (%)</source>
        <translation>标度因数误差，ImuDesk 估计值（%）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Angle turned (deg)</source>
        <translation>转过的角度（deg）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Duration (s)</source>
        <translation>持续时间（s）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Mean rate (deg/s)</source>
        <translation>平均角速度（deg/s）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Time in the 20-100 deg/s band (%)</source>
        <translation>处于 20-100 deg/s 范围内的时间占比（%）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Rate unevenness, std/mean (%)</source>
        <translation>角速度不均匀度，标准差/均值（%）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stopped within +-5 deg of the target</source>
        <translation>停在目标 +-5 deg 以内</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Run met the manual&apos;s conditions</source>
        <translation>本次校准符合手册要求</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Gyro bias along the axis (deg/s)</source>
        <translation>沿转轴的陀螺仪零偏（deg/s）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Axis tilt from sensor z (deg)</source>
        <translation>转轴相对传感器 z 轴的倾角（deg）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Output rate (Hz)</source>
        <translation>输出频率（Hz）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Variant (ATT RST)</source>
        <translation>模式（ATT RST）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Command sent</source>
        <translation>已发送指令</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Still for, when sent (s)</source>
        <translation>发送时已静止时长（s）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Gyro spread, when sent (deg/s)</source>
        <translation>发送时陀螺仪波动（deg/s）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Accelerometer spread, when sent (G)</source>
        <translation>发送时加速度计波动（G）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Roll before (deg)</source>
        <translation>复位前横滚角（deg）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Pitch before (deg)</source>
        <translation>复位前俯仰角（deg）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Roll after (deg)</source>
        <translation>复位后横滚角（deg）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Pitch after (deg)</source>
        <translation>复位后俯仰角（deg）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Yaw after (deg)</source>
        <translation>复位后航向角（deg）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Method</source>
        <translation>方法</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Start command byte</source>
        <translation>启动指令字节</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>FitErr (module&apos;s fit error)</source>
        <translation>FitErr（模块的拟合误差）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>FitErr limit (manual)</source>
        <translation>FitErr 上限（手册）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Points used</source>
        <translation>使用点数</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Valid points collected</source>
        <translation>已采集有效点数</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>unbounded</source>
        <translation>无界</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>yes</source>
        <translation>是</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>no</source>
        <translation>否</translation>
    </message>
    <message>
        <location line="+118"/>
        <source>ImuDesk calibration report: %1</source>
        <translation>ImuDesk 校准报告：%1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Device</source>
        <translation>设备</translation>
    </message>
    <message>
        <location line="-127"/>
        <location line="+127"/>
        <location line="+1"/>
        <location line="+1"/>
        <source>unknown</source>
        <translation>未知</translation>
    </message>
    <message>
        <location line="-187"/>
        <source>Field strength |B| (µT)</source>
        <translation>磁场强度 |B| (µT)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Hard iron x, y, z (µT)</source>
        <translation>硬铁 x, y, z (µT)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Residual RMS (µT)</source>
        <translation>残差 RMS (µT)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Predicted heading error, level module, 68 % bound (deg)</source>
        <translation>预测航向误差，水平模块，68 % 界限（deg）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Predicted heading error, level module, 95 % bound (deg)</source>
        <translation>预测航向误差，水平模块，95 % 界限（deg）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Hard-iron uncertainty, RMS (µT)</source>
        <translation>硬铁不确定度，RMS (µT)</translation>
    </message>
    <message>
        <location line="+176"/>
        <source>Serial number</source>
        <translation>序列号</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Firmware</source>
        <translation>固件</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Time (UTC)</source>
        <translation>时间（UTC）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Calibration</source>
        <translation>校准</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Samples recorded</source>
        <translation>记录的样本数</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Verdict:</source>
        <translation>结论：</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Metrics</source>
        <translation>指标</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Metric</source>
        <translation>指标</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Value</source>
        <translation>数值</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Magnetometer samples</source>
        <translation>磁力计样本</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Troubleshooting (HiPNUC manual v1.7.1, 9.31 and 9.32)</source>
        <translation>故障排查（HiPNUC 手册 v1.7.1，9.31 和 9.32）</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Cause</source>
        <translation>失败原因</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Typical sign</source>
        <translation>典型现象</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>What to do</source>
        <translation>解决方案</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Strong magnetic interference around</source>
        <translation>环境磁场干扰过大</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>STAT=4 or a jumping heading</source>
        <translation>STAT=4 或航向角跳变</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Calibrate outdoors in an open space</source>
        <translation>更换校准环境至室外空旷处</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Rotation not done as described</source>
        <translation>旋转动作不规范</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>PROGRESS grows slowly or stops</source>
        <translation>PROGRESS 增长缓慢或停滞</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Turn fully and evenly about every axis</source>
        <translation>确保每个轴充分旋转，速度均匀</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The module moved while turning</source>
        <translation>旋转时位置移动</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Calibration finishes but the heading is poor</source>
        <translation>校准完成但精度差</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Keep it in place, only turn it</source>
        <translation>校准时保持位置固定，仅旋转姿态</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Module and carrier moved relative to each other</source>
        <translation>模块与载体位置变化</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Larger heading error after remounting</source>
        <translation>重新安装后航向角误差增大</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Calibrate the module and the carrier again, as one</source>
        <translation>将模块与载体作为整体重新校准</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Indoors the field is often distorted in ways no calibration removes: if the heading stays poor after a good calibration, prefer the 6-axis mode there.</source>
        <translation>室内磁场畸变往往无法通过校准消除：如果校准良好后航向角精度仍然较差，在室内请优先使用 6 轴模式。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Written by ImuDesk from the run kept in %1</source>
        <translation>由 ImuDesk 根据 %1 中保存的校准数据生成</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Left: the %1 samples of the run as measured (raw). Right: the same samples corrected by the run&apos;s hard and soft iron; the green cells are the directions they cover, %2 % of the sphere.</source>
        <translation>左：本次校准测得的 %1 个样本（原始数据）。右：用本次的硬铁和软铁校正后的同一批样本；绿色单元为它们覆盖的方向，占球面的 %2 %。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The %1 samples of the run as measured (raw), around their mean; the green cells are the directions they point to. The run has no usable correction to show them corrected.</source>
        <translation>本次校准测得的 %1 个样本（原始数据），以其均值为中心；绿色单元为它们指向的方向。本次没有可用的校正，无法显示校正后的样本。</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>still running</source>
        <translation>仍在运行</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Last reply: STAT=%1, PROGRESS=%2.</source>
        <translation>最后一次应答：STAT=%1，PROGRESS=%2。</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>The device&apos;s own calibration</source>
        <translation>设备自身的校准</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The module&apos;s calibration (MCAL) is a separate run with its own verdict; the verdict and the metrics above are ImuDesk&apos;s fit of the raw samples.</source>
        <translation>模块自身的校准（MCAL）是另一次独立的运行，有自己的结论；上面的结论和指标是 ImuDesk 对原始样本的拟合。</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>ImuDesk calibration report</source>
        <translation>ImuDesk 校准报告</translation>
    </message>
    <message>
        <location filename="../ui/calibration/calibration_history_dialog.cpp" line="+236"/>
        <location filename="../ui/calibration/calibration_report.cpp" line="-11"/>
        <source>Device&apos;s verdict:</source>
        <translation>设备的结论：</translation>
    </message>
</context>
<context>
    <name>CalibrationRunSaver</name>
    <message>
        <location filename="../ui/calibration/calibration_run_saver.cpp" line="+48"/>
        <source>Saved in the calibration history (Calibrate &gt; Calibration history): %1</source>
        <translation>已保存到校准历史（校准 &gt; 校准历史）：%1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>This run could not be saved in the calibration history: %1 The result is still shown here; free some disk space or check the folder&apos;s permissions to keep the next run.</source>
        <translation>本次校准无法保存到校准历史：%1 结果仍显示在此处；请释放一些磁盘空间或检查文件夹权限，以便保存下一次校准。</translation>
    </message>
</context>
<context>
    <name>CanDecoder</name>
    <message>
        <location filename="../core/protocol/can/can_decoder.cpp" line="+71"/>
        <source>unknown</source>
        <translation>未知</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>HEC495 %1 axis: %2</source>
        <translation>HEC495 %1 轴：%2</translation>
    </message>
    <message>
        <location line="+8"/>
        <location line="+92"/>
        <source>HEC495 write 0x%1 confirmed</source>
        <translation>HEC495 写入 0x%1 已确认</translation>
    </message>
    <message>
        <location line="-91"/>
        <location line="+92"/>
        <source>HEC495 write %1</source>
        <translation>HEC495 写入 %1</translation>
    </message>
    <message>
        <location line="-78"/>
        <source>PGN %1 %2: date unknown, not UTC (module clock %3:%4:%5.%6)</source>
        <translation>PGN %1 %2：日期未知，不是 UTC（模块时钟 %3:%4:%5.%6）</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>PGN %1 %2: %3-%4-%5 %6:%7:%8.%9</source>
        <translation>PGN %1 %2：%3-%4-%5 %6:%7:%8.%9</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>heading %1 deg (CW); %2</source>
        <translation>航向角 %1 deg（顺时针）；%2</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>PGN %1: %2</source>
        <translation>PGN %1：%2</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>config %1 -&gt; %2: %3</source>
        <translation>配置 %1 -&gt; %2：%3</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>NMT command 0x%1 to node %2</source>
        <translation>发往节点 %2 的 NMT 指令 0x%1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>SYNC</source>
        <translation>SYNC</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>heartbeat node %1: %2</source>
        <translation>节点 %1 心跳：%2</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>node %1: </source>
        <translation>节点 %1： </translation>
    </message>
    <message>
        <location line="+0"/>
        <source>to node %1: </source>
        <translation>发往节点 %1： </translation>
    </message>
    <message>
        <location line="+14"/>
        <source>HEC495 PDO %1 (%2): %3</source>
        <translation>HEC495 PDO %1（%2）：%3</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>fixed</source>
        <translation>定点</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>float</source>
        <translation>浮点</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>TPDO%1 %2: %3</source>
        <translation>TPDO%1 %2：%3</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>TPDO with a wrong length (%1 bytes)</source>
        <translation>长度错误的 TPDO（%1 字节）</translation>
    </message>
</context>
<context>
    <name>CanSettingCatalog</name>
    <message>
        <location filename="../core/protocol/can/can_setting_catalog.cpp" line="+79"/>
        <source>default</source>
        <translation>默认</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>reversed</source>
        <translation>反向</translation>
    </message>
    <message>
        <location line="+79"/>
        <source>UTC time (FF2F) interval</source>
        <translation>UTC 时间 (FF2F) 发送间隔</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Acceleration (FF34) interval</source>
        <translation>加速度 (FF34) 发送间隔</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Angular rate (FF37) interval</source>
        <translation>角速度 (FF37) 发送间隔</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Magnetic field (FF3A) interval</source>
        <translation>磁场 (FF3A) 发送间隔</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Pitch and roll (FF3D) interval</source>
        <translation>俯仰横滚 (FF3D) 发送间隔</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Heading (FF41) interval</source>
        <translation>航向角 (FF41) 发送间隔</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Quaternion (FF46) interval</source>
        <translation>四元数 (FF46) 发送间隔</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Inclinometer (FF4A) interval</source>
        <translation>倾角仪 (FF4A) 发送间隔</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CAN FD frame 0 (FF5A) interval</source>
        <translation>CAN FD 数据帧 0 (FF5A) 发送间隔</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>only on a module with CAN FD output enabled; the manual gives no command to enable it</source>
        <translation>仅在启用 CAN FD 输出的模块上有效；手册未给出启用它的命令</translation>
    </message>
    <message>
        <location line="-123"/>
        <source>CAN bit rate</source>
        <translation>CAN 波特率</translation>
    </message>
    <message>
        <location line="+77"/>
        <source>the serial port&apos;s baud rate; takes effect after save and reset</source>
        <translation>串口波特率；保存并复位后生效</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the Modbus address of the serial port</source>
        <translation>串口的 Modbus 地址</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>6-axis (relative heading)</source>
        <translation>6 轴（相对航向）</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>9-axis (absolute heading)</source>
        <translation>9 轴（绝对航向）</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>v1.6.6: 0-4; v1.7.1: the URFR code (0x18 = 024 ...); the manual gives no read</source>
        <translation>v1.6.6：0-4；v1.7.1：URFR 代码（0x18 = 024 ...）；手册未给出读取方法</translation>
    </message>
    <message>
        <location line="+5"/>
        <location line="+233"/>
        <source>read only</source>
        <translation>只读</translation>
    </message>
    <message>
        <location line="-204"/>
        <location line="+47"/>
        <location line="+3"/>
        <source>takes effect after save and reset</source>
        <translation>保存并复位后生效</translation>
    </message>
    <message>
        <location line="-49"/>
        <source>Source address (node ID)</source>
        <translation>源地址（节点 ID）</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+81"/>
        <source>Data output</source>
        <translation>数据输出</translation>
    </message>
    <message>
        <location line="-79"/>
        <location line="+67"/>
        <location line="+14"/>
        <source>off</source>
        <translation>关</translation>
    </message>
    <message>
        <location line="-81"/>
        <location line="+81"/>
        <source>on</source>
        <translation>开</translation>
    </message>
    <message>
        <location line="-79"/>
        <location line="+45"/>
        <source>Inclinometer X direction</source>
        <translation>倾角仪 X 轴方向</translation>
    </message>
    <message>
        <location line="-43"/>
        <location line="+45"/>
        <source>Inclinometer Y direction</source>
        <translation>倾角仪 Y 轴方向</translation>
    </message>
    <message>
        <location line="-43"/>
        <source>Firmware version</source>
        <translation>固件版本</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>TPDO%1 (%2) period</source>
        <translation>TPDO%1（%2）周期</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+14"/>
        <source>0 = off</source>
        <translation>0 = 关闭</translation>
    </message>
    <message>
        <location line="-12"/>
        <source>TPDO%1 transmission</source>
        <translation>TPDO%1 传输方式</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>on each SYNC</source>
        <translation>每个 SYNC 发送</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>timed (0xFE)</source>
        <translation>定时 (0xFE)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>timed (0xFF)</source>
        <translation>定时 (0xFF)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Heartbeat period</source>
        <translation>心跳周期</translation>
    </message>
    <message>
        <location line="+7"/>
        <location line="+45"/>
        <source>Node ID</source>
        <translation>节点 ID</translation>
    </message>
    <message>
        <location line="-31"/>
        <source>written only: the manual documents no way to read it back</source>
        <translation>只能写入：手册未说明如何读回</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Output rate</source>
        <translation>输出速率</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 Hz</source>
        <translation>%1 Hz</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>PDO mode</source>
        <translation>PDO 模式</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>float</source>
        <translation>浮点</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>fixed point</source>
        <translation>定点</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>float, 0x180/0x280 only</source>
        <translation>浮点，仅 0x180/0x280</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Work mode</source>
        <translation>工作模式</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>angles, acceleration, rate</source>
        <translation>角度、加速度、角速度</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>rate at 500 Hz</source>
        <translation>角速度 500 Hz</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Heartbeat (100 ms x (N + 1))</source>
        <translation>心跳（100 ms × (N + 1)）</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+4"/>
        <source>takes effect after a power cycle</source>
        <translation>重新上电后生效</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>code %1 (not in the manual)</source>
        <translation>代码 %1（手册中没有）</translation>
    </message>
    <message>
        <location line="+39"/>
        <source>%1 is read only</source>
        <translation>%1 为只读</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>%1: &quot;%2&quot; is not a number (%3)</source>
        <translation>%1：“%2”不是数字（%3）</translation>
    </message>
    <message>
        <location line="+9"/>
        <location line="+3"/>
        <source>%1 takes %2</source>
        <translation>%1 可取 %2</translation>
    </message>
</context>
<context>
    <name>CanSurvey</name>
    <message>
        <location filename="../core/discovery/can_survey.cpp" line="+67"/>
        <source>node %1 sent its boot-up message twice while the bus was only listened to: two devices started with that node ID</source>
        <translation>仅监听总线期间，节点 %1 发送了两次启动报文：有两台设备以该节点 ID 启动</translation>
    </message>
    <message>
        <location line="+84"/>
        <source>SDO read of %1:%2</source>
        <translation>对 %1:%2 的 SDO 读取</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>J1939 read of register %1</source>
        <translation>对寄存器 %1 的 J1939 读取</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>refused</source>
        <translation>被拒绝</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 answers from node %2 to one %3, with different contents (%4)</source>
        <translation>节点 %2 对同一次%3给出 %1 个应答，内容不同（%4）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 answers from node %2 to one %3 (%4)</source>
        <translation>节点 %2 对同一次%3给出 %1 个应答（%4）</translation>
    </message>
    <message>
        <location line="+51"/>
        <source>HiPNUC module (J1939)</source>
        <translation>HiPNUC 模块（J1939）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>HiPNUC module (CANopen)</source>
        <translation>HiPNUC 模块（CANopen）</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>vendor %1, product code %2</source>
        <translation>厂商 %1，产品代码 %2</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>the module&apos;s own bit-rate setting (the interface cannot measure one)</source>
        <translation>模块自身的波特率设置（该接口无法测得波特率）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>sends no data; answered when asked</source>
        <translation>不主动发送数据；询问时有应答</translation>
    </message>
    <message numerus="yes">
        <location line="+8"/>
        <source>%1 (and %n more time(s) like it)</source>
        <translation>
            <numerusform>%1（另有 %n 次同类情况）</numerusform>
        </translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Power the devices one at a time and give each its own node ID (its CAN tab, Settings, node ID; save and reset), then sweep again.</source>
        <translation>逐台给设备上电，并为每台设置各自的节点 ID（在其 CAN 标签页的“设置”中修改节点 ID，保存并复位），然后重新扫描。</translation>
    </message>
</context>
<context>
    <name>CanUi</name>
    <message>
        <location filename="../ui/families/can_ui.cpp" line="+20"/>
        <source>CAN %1:%2</source>
        <translation>CAN %1:%2</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>CAN frames</source>
        <translation>CAN 帧</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>CAN configuration</source>
        <translation>CAN 配置</translation>
    </message>
</context>
<context>
    <name>CanUpdateFlow</name>
    <message>
        <location filename="../core/firmware/can_update_flow.cpp" line="+35"/>
        <source>unknown</source>
        <translation>未知</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>idle</source>
        <translation>空闲</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>checking the image</source>
        <translation>正在检查镜像</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>identifying the module</source>
        <translation>正在识别模块</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>entering the bootloader</source>
        <translation>正在进入引导程序</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>confirming the bootloader</source>
        <translation>正在确认引导程序</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>downloading</source>
        <translation>正在下载</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>verifying</source>
        <translation>正在校验</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>starting the application</source>
        <translation>正在启动应用程序</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>confirming the new version</source>
        <translation>正在确认新版本</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>done</source>
        <translation>完成</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>failed</source>
        <translation>失败</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cancelled</source>
        <translation>已取消</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>the image is empty</source>
        <translation>镜像为空</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the image starts at %1, but the CAN bootloader writes the application at %2 (addresses are not transmitted); this is not an application image for this module</source>
        <translation>镜像起始地址为 %1，但 CAN 引导程序固定将应用程序写入 %2（地址不随数据传输）；这不是本模块的应用程序镜像</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the image ends at %1, beyond the end of the flash at %2; it does not fit this module</source>
        <translation>镜像结束地址 %1 超出闪存末尾 %2；不适用于本模块</translation>
    </message>
    <message>
        <location line="+92"/>
        <source>the application refused to enter its bootloader (0x1F51:05): %1</source>
        <translation>应用程序拒绝进入引导程序（0x1F51:05）：%1</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>the bootloader refused the confirmation (0x1F51:06): %1</source>
        <translation>引导程序拒绝了确认请求（0x1F51:06）：%1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>no bootloader confirmation yet (attempt %1 of %2)</source>
        <translation>引导程序尚未确认（第 %1 次尝试，共 %2 次）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the module did not confirm its bootloader (0x1F51:06) after %1 attempts; check the node ID and power-cycle the module</source>
        <translation>尝试 %1 次后，模块仍未确认进入引导程序（0x1F51:06）；请检查节点 ID，并将模块断电重启</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>cancelled after %1 of %2 bytes</source>
        <translation>已在传输 %1 / %2 字节后取消</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>the reply to segment %1 does not echo its data (%2); the reply is damaged</source>
        <translation>分段 %1 的应答未回显其数据（%2）；应答已损坏</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>the bootloader did not accept the download of %1 bytes within %2 ms (it erases first)</source>
        <translation>引导程序未在 %2 ms 内接受 %1 字节的下载（它会先擦除闪存）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>no reply to segment %1 (byte %2 of %3) within %4 ms</source>
        <translation>分段 %1（第 %2 / %3 字节）在 %4 ms 内无应答</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>the bootloader refused the download of %1 bytes: %2</source>
        <translation>引导程序拒绝了 %1 字节的下载：%2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>segment %1 (byte %2 of %3): %4</source>
        <translation>分段 %1（第 %2 / %3 字节）：%4</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the bootloader accepted %1 bytes (erase took %2 ms)</source>
        <translation>引导程序已接受 %1 字节（擦除耗时 %2 ms）</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>the application did not answer within %1 s after the start (no boot-up, heartbeat or SDO reply); the image may not be a firmware for this module</source>
        <translation>启动后 %1 s 内应用程序无应答（无启动报文、心跳或 SDO 应答）；该镜像可能不是本模块的固件</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>refused before contacting the module: %1</source>
        <translation>在联系模块之前已拒绝：%1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>refused: node %1 is not a CANopen node ID (1..127)</source>
        <translation>已拒绝：%1 不是有效的 CANopen 节点 ID（1..127）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>image: %1 bytes at %2, CRC-32 %3</source>
        <translation>镜像：%1 字节，位于 %2，CRC-32 %3</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>node %1: application answers, firmware %2</source>
        <translation>节点 %1：应用程序已应答，固件 %2</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>nothing answered on node %1: neither the application (SDO 0x1018:3) nor the bootloader (0x1F51:06). Check the node ID, the bit rate, the termination and the power</source>
        <translation>节点 %1 无任何应答：应用程序（SDO 0x1018:3）和引导程序（0x1F51:06）均无应答。请检查节点 ID、波特率、终端电阻和电源</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the module is already in its bootloader (an earlier update was interrupted); run the update again and allow finishing it</source>
        <translation>模块已处于引导程序中（之前的更新被中断）；请重新执行更新，并让其完成</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the module is already in its bootloader: an earlier update was interrupted; finishing it</source>
        <translation>模块已处于引导程序中：之前的更新被中断；正在完成该更新</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>cancelled; the module was not changed</source>
        <translation>已取消；模块未被修改</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>cancelled before the download; the module was not changed (if it is in its bootloader, run the update again)</source>
        <translation>下载前已取消；模块未被修改（如果模块处于引导程序中，请重新执行更新）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>bootloader confirmed on node %1</source>
        <translation>节点 %1 已确认进入引导程序</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>cancelled before the download; the module stays in its bootloader; run the update again to finish it</source>
        <translation>下载前已取消；模块停留在引导程序中；请重新执行更新以完成</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>cancelled before the download; the application was restarted unchanged</source>
        <translation>下载前已取消；应用程序已原样重启</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1. The module stays in its bootloader without a valid application; run the update again to finish it</source>
        <translation>%1。模块停留在引导程序中，没有有效的应用程序；请重新执行更新以完成</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the download failed: %1. The module stays in its bootloader; run the update again</source>
        <translation>下载失败：%1。模块停留在引导程序中；请重新执行更新</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 bytes sent in %2 s (%3 bytes/s)</source>
        <translation>%2 s 内发送 %1 字节（%3 字节/秒）</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>verification failed: the bootloader reports CRC-32 %1 for the written application, the image has %2. The application was not started; run the update again</source>
        <translation>校验失败：引导程序报告已写入应用程序的 CRC-32 为 %1，而镜像的为 %2。应用程序未启动；请重新执行更新</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>verified: bootloader CRC %1 equals the image&apos;s</source>
        <translation>校验通过：引导程序 CRC %1 与镜像一致</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the bootloader offers no CRC (0x1F56:1 %1); the restart of the application is the only check</source>
        <translation>引导程序不提供 CRC（0x1F56:1 %1）；应用程序能否重启是唯一的检查</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not answered</source>
        <translation>未应答</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>the bootloader refused to start the application (0x1F51:09): %1. Run the update again</source>
        <translation>引导程序拒绝启动应用程序（0x1F51:09）：%1。请重新执行更新</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the image was sent but %1</source>
        <translation>镜像已发送，但%1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>updated: firmware %1 → %2, %3 bytes, verified: bootloader CRC %4</source>
        <translation>已更新：固件 %1 → %2，%3 字节，已校验：引导程序 CRC %4</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>updated: %1 bytes sent; not verified by the bootloader; application restarted with version %2</source>
        <translation>已更新：已发送 %1 字节；未经引导程序校验；应用程序已重启，版本 %2</translation>
    </message>
</context>
<context>
    <name>CaptureExporter</name>
    <message>
        <location filename="../core/record/capture_exporter.cpp" line="+116"/>
        <location line="+118"/>
        <location line="+6"/>
        <source>Cannot write %1: %2</source>
        <translation>无法写入 %1：%2</translation>
    </message>
    <message>
        <location line="-132"/>
        <location line="+174"/>
        <location line="+28"/>
        <source>Writing %1 failed: %2. Check the free disk space.</source>
        <translation>写入 %1 失败：%2。请检查磁盘剩余空间。</translation>
    </message>
    <message>
        <location line="-59"/>
        <source>The capture holds %1 frame types; the vendor layout has a file for each: %2</source>
        <translation>该记录含有 %1 种帧类型；厂商格式为每种各写一个文件：%2</translation>
    </message>
    <message>
        <location line="+215"/>
        <source>No output file was given.</source>
        <translation>未指定输出文件。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The time range is empty (from %1 s to %2 s).</source>
        <translation>时间范围为空（从 %1 s 到 %2 s）。</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>The module reports its attitude in North-West-Up (CONFIG IMU COORD 4); the vendor CSV&apos;s layout has no column to say so: its angles and quaternion are NWU.</source>
        <translation>模块以北西天（NWU）坐标系输出姿态（CONFIG IMU COORD 4）；厂商 CSV 的格式没有列可以注明：其中的角度和四元数均为 NWU。</translation>
    </message>
    <message>
        <location line="+47"/>
        <source>Export cancelled.</source>
        <translation>导出已取消。</translation>
    </message>
    <message numerus="yes">
        <location line="+10"/>
        <source>%n damaged chunk(s) were skipped</source>
        <translation>
            <numerusform>已跳过 %n 个损坏的数据块</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>CaptureHeader</name>
    <message>
        <location filename="../core/capture/capture_header.cpp" line="+146"/>
        <source>line %1 of the capture header is not a key=value entry</source>
        <translation>记录文件头第 %1 行不是“键=值”格式的条目</translation>
    </message>
</context>
<context>
    <name>CaptureReader</name>
    <message>
        <location filename="../core/capture/capture_reader.cpp" line="+43"/>
        <source>Cannot open %1: %2</source>
        <translation>无法打开 %1：%2</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <location line="+66"/>
        <source>not an ImuDesk capture file (it does not start with IMUDCAP1); raw byte dumps are read by &apos;imudesk-cli decode&apos;</source>
        <translation>不是 ImuDesk 记录文件（文件开头不是 IMUDCAP1）；原始字节转储文件请用“imudesk-cli decode”读取</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>capture format version %1 is newer than this ImuDesk reads (%2); update ImuDesk</source>
        <translation>记录文件格式版本 %1 高于本 ImuDesk 可读取的版本（%2）；请更新 ImuDesk</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the capture header claims %1 bytes (at most %2): the file is damaged</source>
        <translation>记录文件头声明长度为 %1 字节（最多 %2）：文件已损坏</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the file ends inside the capture header: nothing was recorded</source>
        <translation>文件在记录文件头内结束：未记录任何数据</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the capture header&apos;s CRC does not match: the file is damaged</source>
        <translation>记录文件头的 CRC 不匹配：文件已损坏</translation>
    </message>
    <message>
        <location line="+59"/>
        <location line="+31"/>
        <source>the file ends inside a chunk at offset %1 (recording was interrupted); everything before it was read</source>
        <translation>文件在偏移 %1 处的数据块内结束（记录被中断）；此前的内容均已读取</translation>
    </message>
    <message>
        <location line="-21"/>
        <source>damaged chunk at offset %1 (bad framing); skipped</source>
        <translation>偏移 %1 处的数据块已损坏（帧结构错误）；已跳过</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>damaged chunk at offset %1 (bad length); skipped</source>
        <translation>偏移 %1 处的数据块已损坏（长度错误）；已跳过</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>damaged chunk at offset %1 (CRC mismatch); skipped</source>
        <translation>偏移 %1 处的数据块已损坏（CRC 不匹配）；已跳过</translation>
    </message>
</context>
<context>
    <name>CaptureSource</name>
    <message>
        <location filename="../core/record/capture_source.cpp" line="+46"/>
        <source>%1 cannot be read: %2</source>
        <translation>无法读取 %1：%2</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 is empty</source>
        <translation>%1 是空文件</translation>
    </message>
    <message>
        <location line="+108"/>
        <source>No temporary folder to convert %1 in: %2</source>
        <translation>没有可用于转换 %1 的临时文件夹：%2</translation>
    </message>
    <message numerus="yes">
        <location line="-38"/>
        <source>%1 is a vendor CSV: %n row(s) read, times from its pc_counter column</source>
        <translation>
            <numerusform>%1 是厂商 CSV：已读取 %n 行，时间取自 pc_counter 列</numerusform>
        </translation>
    </message>
    <message>
        <location line="-54"/>
        <source>%1 is neither an ImuDesk capture nor %2</source>
        <translation>%1 既不是 ImuDesk 记录文件，也不是%2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 is neither an ImuDesk capture, %2 nor %3</source>
        <translation>%1 既不是 ImuDesk 记录文件，也不是%2或%3</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>%1 is already an ImuDesk capture</source>
        <translation>%1 已经是 ImuDesk 记录文件</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>%1 malformed lines in all</source>
        <translation>共 %1 行格式错误</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 is a raw byte dump without arrival times: the times shown come from the device&apos;s own clock</source>
        <translation>%1 是原始字节转储，没有接收时间：显示的时间取自设备自身的时钟</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 is a raw byte dump without arrival times, and nothing in it carries a device time: every time is 0</source>
        <translation>%1 是原始字节转储，没有接收时间，其中也没有任何设备时间：所有时间均为 0</translation>
    </message>
    <message numerus="yes">
        <location line="+4"/>
        <source>The device clock restarted or jumped %n time(s); the times go on across each jump.</source>
        <translation>
            <numerusform>设备时钟重启或跳变了 %n 次；时间在每次跳变处连续延续。</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>CaptureWriter</name>
    <message>
        <location filename="../core/capture/capture_writer.cpp" line="+94"/>
        <source>Cannot create the capture file %1: %2. Choose a folder you can write to.</source>
        <translation>无法创建记录文件 %1：%2。请选择有写入权限的文件夹。</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Cannot write the capture file %1: %2. Check the free disk space.</source>
        <translation>无法写入记录文件 %1：%2。请检查磁盘剩余空间。</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>Recording stopped: the disk cannot keep up (more than %1 MB waiting to be written). Record to a faster disk.</source>
        <translation>记录已停止：磁盘写入速度跟不上（超过 %1 MB 数据等待写入）。请记录到速度更快的磁盘。</translation>
    </message>
    <message>
        <location line="+108"/>
        <source>Recording stopped: writing %1 failed (%2). Everything up to that point is in the file; free some disk space and record again.</source>
        <translation>记录已停止：写入 %1 失败（%2）。此前的数据均已保存在文件中；请释放一些磁盘空间后重新记录。</translation>
    </message>
</context>
<context>
    <name>CheckReport</name>
    <message>
        <location filename="../core/verify/gyro_fit.cpp" line="+118"/>
        <source>no still pose</source>
        <translation>没有静止姿态</translation>
    </message>
    <message>
        <location filename="../core/verify/dynamic_check.cpp" line="+56"/>
        <location filename="../core/verify/gyro_fit.cpp" line="+27"/>
        <source>needs the accelerometer calibrated from at least 9 still poses</source>
        <translation>需要先用至少 9 个静止姿态校准加速度计</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>needs a still pose with the module&apos;s attitude to start from</source>
        <translation>需要一个带有模块姿态输出的静止姿态作为起点</translation>
    </message>
    <message>
        <location line="+67"/>
        <source>the module did not move enough between the poses (%1 s, %2° turned; %3 s and %4° needed)</source>
        <translation>模块在静止姿态之间运动不足（运动 %1 s，转过 %2°；需要 %3 s 和 %4°）</translation>
    </message>
    <message>
        <location line="+55"/>
        <source>the module&apos;s attitude follows the reference by more than %1 ms or not at all</source>
        <translation>模块姿态滞后参考超过 %1 ms，或根本不跟随参考</translation>
    </message>
    <message>
        <location filename="../core/verify/gyro_fit.cpp" line="+27"/>
        <source>needs at least 3 turns of more than 20° between still poses (found %1)</source>
        <translation>静止姿态之间需要至少 3 次超过 20° 的转动（找到 %1 次）</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the turns between poses do not pin the gyro&apos;s scale: turn it about each axis while that axis is level</source>
        <translation>姿态之间的转动不足以确定陀螺仪的标度因数：请在各轴水平时绕该轴转动模块</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>the turns between poses do not pin the gyro&apos;s axes (at least 6 turns of more than 20°, about every axis, are needed; found %1)</source>
        <translation>姿态之间的转动不足以确定陀螺仪的轴向（需要至少 6 次超过 20° 且覆盖各轴的转动；找到 %1 次）</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>the turns between poses did not turn the module about its %1 axis enough: turn it about each axis while that axis is level</source>
        <translation>姿态之间的转动中，模块绕其 %1 轴转动不足：请在每个轴保持水平时绕该轴转动模块</translation>
    </message>
    <message>
        <location filename="../core/verify/module_check.cpp" line="+71"/>
        <source>pass</source>
        <translation>通过</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>warn</source>
        <translation>警告</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>fail</source>
        <translation>不合格</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cannot judge</source>
        <translation>无法判定</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>%1: %2 ± %3 %4%5 (95 %), pass at most %6, fail above %7: %8</source>
        <translation>%1：%2 ± %3 %4%5（95 %），不超过 %6 为通过，超过 %7 为不合格：%8</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>%1: cannot judge, %2</source>
        <translation>%1：无法判定，%2</translation>
    </message>
    <message>
        <location line="+40"/>
        <source>hold the module still for 3 s in each of at least %1 orientations (every face up and down, then between them)</source>
        <translation>请在至少 %1 个朝向上各让模块静止 3 s（每个面分别朝上和朝下，再加上介于它们之间的朝向）</translation>
    </message>
    <message>
        <location line="+25"/>
        <location line="+10"/>
        <source>no still pose: %1</source>
        <translation>没有静止姿态：%1</translation>
    </message>
    <message>
        <location line="-8"/>
        <source>%1 distinct still poses, %2 needed: %3</source>
        <translation>只有 %1 个不同的静止姿态，需要 %2 个：%3</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the poses do not pin the accelerometer&apos;s errors: %1</source>
        <translation>这些姿态不足以确定加速度计的误差：%1</translation>
    </message>
    <message>
        <location line="+45"/>
        <source>accelerometer bias</source>
        <translation>加速度计零偏</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>accelerometer scale error</source>
        <translation>加速度计标度因数误差</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>accelerometer misalignment</source>
        <translation>加速度计轴间失准</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>gyro bias</source>
        <translation>陀螺仪零偏</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>gyro scale error</source>
        <translation>陀螺仪标度因数误差</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>gyro misalignment</source>
        <translation>陀螺仪轴间失准</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>roll error</source>
        <translation>横滚误差</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>pitch error</source>
        <translation>俯仰误差</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>heading error</source>
        <translation>航向误差</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>attitude error while moving (RMS)</source>
        <translation>运动中的姿态误差（RMS）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>attitude lag</source>
        <translation>姿态滞后</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>the bench&apos;s gravity was not given: standard gravity (9.80665 m/s²) assumed, its uncertainty (±0.3 %) is in the scale figures; give --gravity or --latitude and --height</source>
        <translation>未给出测试台处的重力加速度：已按标准重力（9.80665 m/s²）计算，其不确定度（±0.3 %）已计入标度因数的数值；请给出 --gravity，或 --latitude 和 --height</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>a hard iron of %1 µT (the poses&apos; fields off centre) was removed for the heading reference: calibrate the magnetometer</source>
        <translation>为得到航向参考，已扣除 %1 µT 的硬铁（各姿态的磁场偏离中心）：请校准磁力计</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>pose at %1 s set aside for the heading: %2</source>
        <translation>%1 s 处的姿态已从航向判定中剔除：%2</translation>
    </message>
    <message>
        <location filename="../core/verify/pose_attitude.cpp" line="+98"/>
        <source>needs the accelerometer calibrated from at least 9 still poses: an uncalibrated one is no reference for the tilt</source>
        <translation>需要先用至少 9 个静止姿态校准加速度计：未校准的加速度计不能作为倾角的参考</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>pitch %1°: roll and heading have no meaning near ±90°</source>
        <translation>俯仰角 %1°：在 ±90° 附近，横滚和航向没有意义</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>needs at least 3 still poses with the module&apos;s attitude and a pitch within ±%1° (found %2)</source>
        <translation>需要至少 3 个带有模块姿态输出、且俯仰角在 ±%1° 以内的静止姿态（找到 %2 个）</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>needs at least 3 still poses with a magnetometer, the module&apos;s attitude and a pitch within ±%1° (found %2)</source>
        <translation>需要至少 3 个带有磁力计数据和模块姿态输出、且俯仰角在 ±%1° 以内的静止姿态（找到 %2 个）</translation>
    </message>
    <message>
        <location line="+47"/>
        <source>field %1 µT, %2 % from the other poses&apos;: a magnetic disturbance here</source>
        <translation>磁场 %1 µT，与其他姿态的磁场相差 %2 %：此处有磁干扰</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>field inclination %1°, %2° from the other poses&apos;: a magnetic disturbance here</source>
        <translation>磁倾角 %1°，与其他姿态的磁倾角相差 %2°：此处有磁干扰</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>the magnetic field disagreed between the poses (%1 of %2 set aside): calibrate the magnetometer, move away from steel and motors, and record again</source>
        <translation>各姿态的磁场不一致（%2 个中剔除了 %1 个）：请校准磁力计，远离钢铁和电机，然后重新录制</translation>
    </message>
    <message>
        <location filename="../core/verify/compass_check.cpp" line="+106"/>
        <source>the compass was not held still for %1 s at the bearings %2°: turn it to each marked bearing of a level compass rose and hold it there</source>
        <translation>罗盘未在方位 %2° 处静止保持 %1 s：请在水平的罗经盘上将它依次转到每个标记方位并保持不动</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>heading error: cannot judge, %1</source>
        <translation>航向误差：无法判定，%1</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>%1: %2 ± %3 ° (95 %), pass at most %4, fail above %5: %6</source>
        <translation>%1：%2 ± %3 °（95 %），不超过 %4 为通过，超过 %5 为不合格：%6</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>heading error at %1°, the worst bearing</source>
        <translation>%1° 处的航向误差（最差方位）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>heading offset, mean of the bearings</source>
        <translation>航向偏移（各方位平均）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>pitch on the level rose</source>
        <translation>水平罗经盘上的俯仰</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>roll on the level rose</source>
        <translation>水平罗经盘上的横滚</translation>
    </message>
</context>
<context>
    <name>CompassPoseTracker</name>
    <message>
        <location filename="../core/calib/compass_pose_tracker.cpp" line="+102"/>
        <source>Automatic 12-point</source>
        <translation>自动 12 点</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Manual</source>
        <translation>手动</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Automatic all-orientation</source>
        <translation>自动全姿态</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>12-point small tilt</source>
        <translation>12 点小倾角</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Planar</source>
        <translation>平面</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Turn the compass, together with everything mounted with it, to each of the 12 poses shown; it collects a point by itself near each one. Needs pitch beyond 45 deg and roll beyond 30 deg.</source>
        <translation>将罗盘连同与其一起安装的所有部件转到图示的 12 个姿态；在每个姿态附近会自动采集一个点。需要俯仰角超过 45 deg、横滚角超过 30 deg。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Turn the compass to the poses it will be used in and collect a point at each (at least 12); spread the headings evenly.</source>
        <translation>将罗盘转到实际使用时的各个姿态，并在每个姿态采集一个点（至少 12 个）；航向角应均匀分布。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Start level. Turn 2-3 times about the vertical axis (10-15 s per turn, speeding up and slowing down), then 1-2 times about X and Y (about 10 s per turn), then at random so that every orientation is reached. Up to 96 points.</source>
        <translation>从水平位置开始。先绕竖直轴转 2-3 圈（每圈 10-15 s，时快时慢），再绕 X 轴和 Y 轴各转 1-2 圈（每圈约 10 s），然后随意转动，使其经过所有姿态。最多 96 个点。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>For roll below 5 deg: keep it nearly level in roll and turn to the 12 headings and pitches shown (pitch beyond 45 deg).</source>
        <translation>适用于横滚角小于 5 deg 的场合：横滚方向保持接近水平，转到图示的 12 个航向角和俯仰角（俯仰角超过 45 deg）。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Place the compass level (pitch and roll below 2 deg) and turn it one full circle slowly and evenly. Up to 12 points.</source>
        <translation>将罗盘水平放置（俯仰角和横滚角小于 2 deg），缓慢匀速地转动一整圈。最多 12 个点。</translation>
    </message>
    <message>
        <location line="+80"/>
        <source>%1 points collected, at least %2 needed.</source>
        <translation>已采集 %1 个点，至少需要 %2 个。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 points collected: you can save the calibration.</source>
        <translation>已采集 %1 个点：可以保存校准结果。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Point %1: heading %2 deg, pitch %3..%4 deg, roll %5..%6 deg</source>
        <translation>第 %1 点：航向角 %2 deg，俯仰角 %3..%4 deg，横滚角 %5..%6 deg</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>All %1 points collected: save the calibration.</source>
        <translation>全部 %1 个点已采集：请保存校准结果。</translation>
    </message>
</context>
<context>
    <name>ConfigProfile</name>
    <message>
        <location filename="../core/settings/config_profile.cpp" line="+55"/>
        <source>the profile is larger than %1 KiB: not an ImuDesk profile</source>
        <translation>配置文件大于 %1 KiB：不是 ImuDesk 配置文件</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the profile is not valid JSON (%1 at byte %2)</source>
        <translation>配置文件不是有效的 JSON（第 %2 字节处：%1）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the profile must be a JSON object</source>
        <translation>配置文件必须是一个 JSON 对象</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>not an ImuDesk profile (&quot;format&quot; must be &quot;imudesk-profile&quot;)</source>
        <translation>不是 ImuDesk 配置文件（&quot;format&quot; 必须为 &quot;imudesk-profile&quot;）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>profile version %1 is not supported (this ImuDesk reads version %2)</source>
        <translation>不支持配置文件版本 %1（本 ImuDesk 读取版本 %2）</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&quot;device&quot; must be an object</source>
        <translation>&quot;device&quot; 必须是一个对象</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>&quot;settings&quot; must be an object of &quot;KEY&quot;: &quot;VALUE&quot;</source>
        <translation>&quot;settings&quot; 必须是由 &quot;KEY&quot;: &quot;VALUE&quot; 组成的对象</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>too many settings (%1)</source>
        <translation>设置项过多（%1）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>unknown setting &apos;%1&apos; in the profile</source>
        <translation>配置文件中有未知设置项“%1”</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the value of %1 must be a string</source>
        <translation>%1 的值必须是字符串</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>cannot write %1: %2</source>
        <translation>无法写入 %1：%2</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>cannot read %1: %2</source>
        <translation>无法读取 %1：%2</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 is larger than %2 KiB: not an ImuDesk profile</source>
        <translation>%1 大于 %2 KiB：不是 ImuDesk 配置文件</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
</context>
<context>
    <name>ConvertedCapture</name>
    <message>
        <location filename="../core/capture/converted_capture.cpp" line="+15"/>
        <source>Cannot write %1: %2</source>
        <translation>无法写入 %1：%2</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>Writing %1 failed: %2. Check the free disk space.</source>
        <translation>写入 %1 失败：%2。请检查磁盘剩余空间。</translation>
    </message>
</context>
<context>
    <name>FamilyUi</name>
    <message>
        <location filename="../ui/workspace/family_ui.cpp" line="+22"/>
        <source>Disconnect first, then connect to %1.</source>
        <translation>请先断开连接，再连接 %1。</translation>
    </message>
    <message>
        <location line="+43"/>
        <source>Nothing was opened.</source>
        <translation>没有打开任何连接。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 answered, but ImuDesk has no view for its family.</source>
        <translation>%1 有应答，但 ImuDesk 没有适用于该设备系列的视图。</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Disconnect first, then connect again.</source>
        <translation>请先断开连接，再重新连接。</translation>
    </message>
</context>
<context>
    <name>FileAnalysis</name>
    <message>
        <location filename="../core/record/file_analysis.cpp" line="+45"/>
        <source>Analysis cancelled.</source>
        <translation>分析已取消。</translation>
    </message>
    <message numerus="yes">
        <location line="+9"/>
        <source>%n damaged chunk(s) were skipped</source>
        <translation>
            <numerusform>已跳过 %n 个损坏的数据块</numerusform>
        </translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 holds no IMU frames to analyse</source>
        <translation>%1 中没有可分析的 IMU 数据帧</translation>
    </message>
</context>
<context>
    <name>GyroScaleRun</name>
    <message>
        <location filename="../core/calib/gyro_scale_run.cpp" line="+186"/>
        <source>turn %1 ended at %2 deg, not within %3 deg of %4 deg</source>
        <translation>第 %1 圈停在 %2 deg，未在 %4 deg 的 %3 deg 范围内</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>turn %1 averaged %2 deg/s, outside %3..%4 deg/s</source>
        <translation>第 %1 圈平均角速度为 %2 deg/s，超出 %3..%4 deg/s</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>turn %1 paused on the way</source>
        <translation>第 %1 圈中途有停顿</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>turn %1 was uneven (rate varied by %2 %)</source>
        <translation>第 %1 圈转动不均匀（角速度变化 %2 %）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the module is tilted %1 deg: place it level</source>
        <translation>模块倾斜 %1 deg：请水平放置</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Run not finished (%1 of %2 turns done).</source>
        <translation>校准未完成（已完成 %1 / %2 圈）。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Estimated gyro scale error %1 % (bias %2 deg/s, output rate %3 Hz).</source>
        <translation>陀螺仪标度因数误差估计值 %1 %（零偏 %2 deg/s，输出频率 %3 Hz）。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Estimated gyro scale error %1 %, but the run was not clean: %2. Repeat it.</source>
        <translation>陀螺仪标度因数误差估计值 %1 %，但本次转动不合规范：%2。请重做。</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Place the module level on a flat, steady surface, then start.</source>
        <translation>将模块水平放在平坦、稳固的表面上，然后开始。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Hold the module still (%1 of %2 s).</source>
        <translation>请保持模块静止（%1 / %2 s）。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Turn the module %1 deg (%2 turns) at an even 20-100 deg/s, in either direction.</source>
        <translation>以 20-100 deg/s 的匀速将模块转动 %1 deg（%2 圈），方向不限。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Now turn it back the other way, %1 deg, to the same mark.</source>
        <translation>现在反方向转回 %1 deg，回到同一标记处。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Stop now: on the mark.</source>
        <translation>立即停止：已到标记处。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Too far: %1 deg past the target. Stop and repeat the run.</source>
        <translation>转过头了：超出目标 %1 deg。请停止并重做。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Keep turning, a little faster: %1 deg to go.</source>
        <translation>继续转动，稍快一些：还差 %1 deg。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Keep turning, a little slower: %1 deg to go.</source>
        <translation>继续转动，稍慢一些：还差 %1 deg。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Keep turning evenly: %1 deg to go.</source>
        <translation>继续匀速转动：还差 %1 deg。</translation>
    </message>
</context>
<context>
    <name>HEC495</name>
    <message>
        <location filename="../core/protocol/can/hec495_can.cpp" line="+266"/>
        <source>node ID = %1</source>
        <translation>节点 ID = %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CAN baud = %1 bit/s</source>
        <translation>CAN 波特率 = %1 bit/s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PDO mode = %1</source>
        <translation>PDO 模式 = %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>heartbeat = %1 ms</source>
        <translation>心跳 = %1 ms</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>start PDO</source>
        <translation>启动 PDO</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>stop PDO</source>
        <translation>停止 PDO</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PDO rate = %1 Hz</source>
        <translation>PDO 频率 = %1 Hz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>work mode = 0x%1</source>
        <translation>工作模式 = 0x%1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>object 0x%1 = %2</source>
        <translation>对象 0x%1 = %2</translation>
    </message>
</context>
<context>
    <name>HeadingCheck</name>
    <message>
        <location filename="../core/calib/heading_check.cpp" line="+138"/>
        <source>Passed: %1 deg turned level, the heading followed without a jump (largest step %2 deg).</source>
        <translation>通过：水平转动了 %1°，航向平滑跟随，没有跳变（最大步长 %2°）。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The heading jumped by %1 deg while the module was level and the field steady: the heading does not follow the calibration. Calibrate again (chapter 9.31).</source>
        <translation>模块水平且磁场稳定时航向跳变了 %1°：航向不符合校准。请重新校准（第 9.31 章）。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Keep the module level while you turn it: it is tilted by %1 deg, at most %2 deg is judged. The heading of a tilted module also moves with the tilt, so the check cannot judge it (%3 of %4 deg turned level so far).</source>
        <translation>转动时请保持模块水平：当前倾斜 %1°，最多 %2° 才会被判定。倾斜模块的航向也会随倾斜变化，因此无法据此判定（目前已水平转动 %3°/%4°）。</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>The field is disturbed here (|B| %1 % off the level turn&apos;s): iron, a magnet or a current nearby. The check cannot judge the heading in a disturbed field; move away from it and turn on.</source>
        <translation>此处磁场受到干扰（|B| 偏离水平转动时的值 %1 %）：附近有铁、磁铁或电流。磁场受扰时无法判定航向；请远离干扰源后继续转动。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Keep turning, level and slowly: %1 of %2 deg turned.</source>
        <translation>请保持水平、缓慢地继续转动：已转动 %1°/%2°。</translation>
    </message>
</context>
<context>
    <name>Hec495SerialKind</name>
    <message>
        <location filename="../core/links/hec495_serial_kind.cpp" line="+48"/>
        <source>an HEC495 compass</source>
        <translation>HEC495 罗盘</translation>
    </message>
    <message>
        <location line="+40"/>
        <source>The simulated compass could not start: %1</source>
        <translation>模拟罗盘无法启动：%1</translation>
    </message>
</context>
<context>
    <name>Hec495SerialUi</name>
    <message>
        <location filename="../ui/families/hec495_serial_ui.cpp" line="+22"/>
        <source>Simulated HEC495</source>
        <translation>模拟 HEC495</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>HEC495 on %1</source>
        <translation>%1 上的 HEC495</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Simulated HEC495 compass</source>
        <translation>模拟 HEC495 罗盘</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>Compass</source>
        <translation>罗盘</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Compass settings</source>
        <translation>罗盘设置</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Switch the output to all data</source>
        <translation>将输出切换为全部数据</translation>
    </message>
</context>
<context>
    <name>HipnucRawDumpImport</name>
    <message>
        <location filename="../core/decode/hipnuc_file_import.cpp" line="+186"/>
        <source>a raw dump of what a module sent (HiPNUC frames or NMEA sentences in its first %1 KiB)</source>
        <translation>模块发送内容的原始转储（前 %1 KiB 中含 HiPNUC 帧或 NMEA 语句）</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1 cannot be read: %2</source>
        <translation>无法读取 %1：%2</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Reading %1 failed: %2</source>
        <translation>读取 %1 失败：%2</translation>
    </message>
</context>
<context>
    <name>HipnucSerialKind</name>
    <message>
        <location filename="../core/links/hipnuc_serial_kind.cpp" line="+42"/>
        <source>a HiPNUC module</source>
        <translation>HiPNUC 模块</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>The simulated device could not start: %1</source>
        <translation>模拟设备无法启动：%1</translation>
    </message>
</context>
<context>
    <name>HipnucSerialUi</name>
    <message>
        <location filename="../ui/families/hipnuc_serial_ui.cpp" line="+38"/>
        <location line="+9"/>
        <source>Simulated %1 (firmware %2)</source>
        <translation>模拟 %1（固件 %2）</translation>
    </message>
</context>
<context>
    <name>HipnucVendorCsvImport</name>
    <message>
        <location filename="../core/decode/hipnuc_file_import.cpp" line="-82"/>
        <source>a vendor CSV (first line &quot;HI91,...&quot;)</source>
        <translation>厂商 CSV（首行为“HI91,...”）</translation>
    </message>
</context>
<context>
    <name>HipnucWrites</name>
    <message>
        <location filename="../core/protocol/modbus/hipnuc_writes.cpp" line="+107"/>
        <source>save the configuration to flash</source>
        <translation>将配置保存到闪存</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>restore the factory settings</source>
        <translation>恢复出厂设置</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>reset the module</source>
        <translation>复位模块</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>set the baud rate to %1</source>
        <translation>将波特率设为 %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>set the node ID to %1</source>
        <translation>将节点 ID 设为 %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>switch to 9-axis mode</source>
        <translation>切换到 9 轴模式</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>switch to 6-axis mode</source>
        <translation>切换到 6 轴模式</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>cancel the levelling (value 5)</source>
        <translation>取消调平（值 5）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>level once (value 2, as the manual&apos;s worked example sends it; its register table lists 3)</source>
        <translation>执行一次调平（值 2，与手册示例发送的一致；手册寄存器表列出的是 3）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>level once (value 3, as the manual&apos;s register table defines it)</source>
        <translation>执行一次调平（值 3，按手册寄存器表的定义）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>set the mounting (URFR value %1)</source>
        <translation>设置安装方式（URFR 值 %1）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>write %1 to register 0x%2</source>
        <translation>将 %1 写入寄存器 0x%2</translation>
    </message>
</context>
<context>
    <name>IntelHexLoader</name>
    <message>
        <location filename="../core/protocol/ihex/intel_hex_loader.cpp" line="+37"/>
        <source>line %1: %2</source>
        <translation>第 %1 行：%2</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>the file is %1 bytes, more than the %2 bytes a firmware file may have</source>
        <translation>文件大小为 %1 字节，超过固件文件允许的 %2 字节</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>data after the end-of-file record of line %1; the file is damaged</source>
        <translation>第 %1 行的文件结束记录之后仍有数据；文件已损坏</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>a record must start with &apos;:&apos;; this is not an Intel HEX file</source>
        <translation>记录必须以“:”开头；这不是 Intel HEX 文件</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the record is too short or has an odd number of hex digits; the file is truncated or damaged</source>
        <translation>记录过短或十六进制位数为奇数；文件不完整或已损坏</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>&apos;%1&apos; is not a hex digit</source>
        <translation>“%1”不是十六进制数字</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the record says %1 data bytes but holds %2; the file is truncated or damaged</source>
        <translation>记录声明有 %1 个数据字节，实际为 %2 个；文件不完整或已损坏</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>checksum error (record says %1, bytes give %2); the file is damaged</source>
        <translation>校验和错误（记录中为 %1，按字节计算为 %2）；文件已损坏</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>the record runs past the 4 GiB address space</source>
        <translation>记录超出 4 GiB 地址空间</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>an end-of-file record must have no data and address 0</source>
        <translation>文件结束记录不能包含数据，且地址必须为 0</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>an extended address record must have 2 data bytes and address 0</source>
        <translation>扩展地址记录必须有 2 个数据字节，且地址为 0</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>a start address record must have 4 data bytes and address 0</source>
        <translation>起始地址记录必须有 4 个数据字节，且地址为 0</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>unknown record type %1 (Intel HEX has types 00 to 05)</source>
        <translation>未知记录类型 %1（Intel HEX 的记录类型为 00 至 05）</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the file is empty; choose the firmware&apos;s .hex file</source>
        <translation>文件为空；请选择固件的 .hex 文件</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the file ends without an end-of-file record (type 01); it is truncated, download it again</source>
        <translation>文件缺少文件结束记录（类型 01）；文件不完整，请重新下载</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the file holds no data records</source>
        <translation>文件中没有数据记录</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the record writes %1, which line %2 already wrote (overlapping records); the file is damaged</source>
        <translation>该记录写入 %1，而第 %2 行已写入该地址（记录重叠）；文件已损坏</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>the image spans %1 bytes from %2, more than %3; the addresses are wrong or this is not a firmware for this device</source>
        <translation>镜像从 %2 开始占用 %1 字节，超过 %3；地址有误，或这不是本设备的固件</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>the file is empty; choose the firmware&apos;s .bin file</source>
        <translation>文件为空；请选择固件的 .bin 文件</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the file is %1 bytes, more than %2; this is not a firmware for this device</source>
        <translation>文件大小为 %1 字节，超过 %2；这不是本设备的固件</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the image runs past the 4 GiB address space; check the start address</source>
        <translation>镜像超出 4 GiB 地址空间；请检查起始地址</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>cannot read %1: %2</source>
        <translation>无法读取 %1：%2</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 is %2 bytes, more than the %3 bytes a firmware file may have</source>
        <translation>%1 大小为 %2 字节，超过固件文件允许的 %3 字节</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>a .bin file has no address: give its start address (e.g. 0x8000)</source>
        <translation>.bin 文件不含地址：请指定其起始地址（例如 0x8000）</translation>
    </message>
</context>
<context>
    <name>J1939</name>
    <message>
        <location filename="../core/protocol/can/j1939_config.cpp" line="+104"/>
        <source>PGN %1 interval</source>
        <translation>PGN %1 发送间隔</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>write %1 = %2 ms</source>
        <translation>写入 %1 = %2 ms</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>save configuration</source>
        <translation>保存配置</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>factory defaults</source>
        <translation>恢复出厂设置</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>reset</source>
        <translation>复位</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>command register</source>
        <translation>指令寄存器</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>trigger PGN %1</source>
        <translation>触发 PGN %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>trigger</source>
        <translation>触发</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>CAN baud code</source>
        <translation>CAN 波特率代码</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>node ID</source>
        <translation>节点 ID</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>output enable</source>
        <translation>输出使能</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>inclinometer X sign</source>
        <translation>倾角仪 X 轴符号</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>inclinometer Y sign</source>
        <translation>倾角仪 Y 轴符号</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>attitude reset</source>
        <translation>姿态复位</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>firmware version</source>
        <translation>固件版本</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>register 0x%1</source>
        <translation>寄存器 0x%1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>write %1 = %2 (status %3)</source>
        <translation>写入 %1 = %2（状态 %3）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>read %1 -&gt; %2 (status %3)</source>
        <translation>读取 %1 -&gt; %2（状态 %3）</translation>
    </message>
</context>
<context>
    <name>KbootClient</name>
    <message>
        <location filename="../core/firmware/kboot_client.cpp" line="+58"/>
        <source>%1: only damaged bytes arrived (%2 bytes skipped, %3 CRC errors); the line is noisy or the baud is wrong. Run the update again</source>
        <translation>%1：只收到损坏的字节（跳过 %2 字节，CRC 错误 %3 个）；线路干扰大或波特率不对。请重新执行更新</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: the bootloader did not answer; check the cable and power, then run the update again</source>
        <translation>%1：引导程序无应答；请检查线缆和电源，然后重新执行更新</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>no bootloader answered %1 pings; check the port and baud rate, power-cycle the module and run the update again</source>
        <translation>发送 %1 次探测均无引导程序应答；请检查串口和波特率，将模块断电重启后重新执行更新</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>command 0x%1</source>
        <translation>指令 0x%1</translation>
    </message>
    <message>
        <location line="+11"/>
        <location line="+140"/>
        <source>no ACK for %1</source>
        <translation>%1 未收到 ACK</translation>
    </message>
    <message>
        <location line="-128"/>
        <source>the bootloader aborted %1</source>
        <translation>引导程序中止了 %1</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the bootloader refused %1 %2 times (NAK: damaged on the way); check the cable</source>
        <translation>引导程序 %2 次拒绝 %1（NAK：传输中损坏）；请检查线缆</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>response to command 0x%1</source>
        <translation>指令 0x%1 的响应</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>no %1 within %2 ms</source>
        <translation>%2 ms 内未收到 %1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>malformed %1</source>
        <translation>%1 格式错误</translation>
    </message>
    <message>
        <location line="+8"/>
        <location line="+20"/>
        <source>the bootloader answered command 0x%1 instead of 0x%2</source>
        <translation>引导程序应答的是指令 0x%1，而不是 0x%2</translation>
    </message>
    <message>
        <location line="-14"/>
        <location line="+21"/>
        <source>the bootloader refused command 0x%1: %2</source>
        <translation>引导程序拒绝了指令 0x%1：%2</translation>
    </message>
    <message>
        <location line="-14"/>
        <source>unexpected response 0x%1 to command 0x%2</source>
        <translation>指令 0x%2 收到意外的响应 0x%1</translation>
    </message>
    <message>
        <location line="+69"/>
        <source>data packet %1 (bytes %2..%3 at 0x%4)</source>
        <translation>数据包 %1（位于 0x%4 的字节 %2..%3）</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>the bootloader aborted the transfer at %1: %2</source>
        <translation>引导程序在 %1 处中止了传输：%2</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the bootloader ended the transfer at %1: %2</source>
        <translation>引导程序在 %1 处结束了传输：%2</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>data packet %1 was refused %2 times (NAK); the line is damaging data. Check the cable and run the update again</source>
        <translation>数据包 %1 被拒绝 %2 次（NAK）；线路正在损坏数据。请检查线缆后重新执行更新</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>cancelled after %1 of %2 bytes</source>
        <translation>已在传输 %1 / %2 字节后取消</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>the bootloader offers %1 bytes instead of %2</source>
        <translation>引导程序提供 %1 字节，而不是 %2 字节</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>reading back stopped after %1 of %2 bytes</source>
        <translation>回读在 %1 / %2 字节处停止</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>cancelled while reading back</source>
        <translation>回读时已取消</translation>
    </message>
</context>
<context>
    <name>KbootStatus</name>
    <message>
        <location filename="../core/protocol/kboot/status_code.cpp" line="+55"/>
        <source>success</source>
        <translation>成功</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the operation failed</source>
        <translation>操作失败</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the target is read-only</source>
        <translation>目标为只读</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a value is out of range</source>
        <translation>数值超出范围</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>an argument is invalid</source>
        <translation>参数无效</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the bootloader timed out</source>
        <translation>引导程序超时</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no transfer is in progress</source>
        <translation>当前没有进行中的传输</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the length is not a multiple of the flash unit</source>
        <translation>长度不是闪存编程单元的整数倍</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the address or length is not aligned to a flash sector</source>
        <translation>地址或长度未按闪存扇区对齐</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the address is outside the flash</source>
        <translation>地址超出闪存范围</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>flash access error</source>
        <translation>闪存访问错误</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the region is protected (e.g. the bootloader)</source>
        <translation>该区域受保护（例如引导程序）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the flash command failed</source>
        <translation>闪存指令执行失败</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unknown flash property</source>
        <translation>未知的闪存属性</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>wrong erase key</source>
        <translation>擦除密钥错误</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the region is execute-only</source>
        <translation>该区域仅可执行</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the bootloader does not know this command</source>
        <translation>引导程序不认识此指令</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the command is refused while the chip is secured</source>
        <translation>芯片处于加密状态，拒绝执行此指令</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the data phase was aborted</source>
        <translation>数据阶段已中止</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>ping error</source>
        <translation>探测错误</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no response</source>
        <translation>无响应</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no response expected</source>
        <translation>无需响应</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the bootloader does not support this command</source>
        <translation>引导程序不支持此指令</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the address range is invalid for this memory</source>
        <translation>地址范围对该存储器无效</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>reading the memory failed</source>
        <translation>读取存储器失败</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>writing the memory failed</source>
        <translation>写入存储器失败</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the flash was not erased before writing</source>
        <translation>写入前未擦除闪存</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the bootloader does not know this property</source>
        <translation>引导程序不认识此属性</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the property is read-only</source>
        <translation>该属性为只读</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>invalid property value</source>
        <translation>属性值无效</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>application CRC check passed</source>
        <translation>应用程序 CRC 校验通过</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>application CRC check failed</source>
        <translation>应用程序 CRC 校验失败</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>application CRC check inactive</source>
        <translation>应用程序 CRC 校验未启用</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>application CRC check invalid</source>
        <translation>应用程序 CRC 校验无效</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>application CRC check range out of range</source>
        <translation>应用程序 CRC 校验范围越界</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no ping response</source>
        <translation>探测无响应</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>invalid packet type</source>
        <translation>数据包类型无效</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>packet CRC error</source>
        <translation>数据包 CRC 错误</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no command response</source>
        <translation>指令无响应</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unknown status %1</source>
        <translation>未知状态 %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 (%2): %3</source>
        <translation>%1（%2）：%3</translation>
    </message>
</context>
<context>
    <name>MagCalProcedure</name>
    <message>
        <location filename="../core/calib/mag_cal_procedure.cpp" line="+59"/>
        <source>1. Check the field at the calibration spot: hold the module still and read |B|; 20-60 µT is normal. Below 20 or above 60 µT a magnetic object is near: move away from it or choose another place.
2. Check the rotation: turn about every axis at least 360 deg at 20-100 deg/s, without pausing.
3. Check for spatial interference: measure |B| at the same spot in different orientations. If it varies by more than 10 µT, choose another place or use 6-axis mode.
Keep the module in place while turning it, and calibrate it together with everything mounted to it.</source>
        <translation>1. 检查校准位置的磁场：保持模块静止并读取 |B|；20-60 µT 为正常。低于 20 µT 或高于 60 µT 说明附近有磁性物体：远离它或更换位置。
2. 检查旋转动作：绕每个轴至少旋转 360 deg，速度 20-100 deg/s，中途不要停顿。
3. 检查空间磁场干扰：在同一位置、不同朝向测量 |B|。若变化超过 10 µT，请更换位置或改用 6 轴模式。
旋转时保持模块位置不变，并将模块与所有固联物体作为整体一起校准。</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Starting the calibration on the device.</source>
        <translation>正在设备上启动校准。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>This firmware calibrates in the background in 9-axis mode: turn the module slowly through as many orientations as you can.</source>
        <translation>此固件在 9 轴模式下进行后台校准：请缓慢转动模块，尽可能经过更多姿态。</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>The device did not finish the calibration within %1 s.</source>
        <translation>设备未在 %1 s 内完成校准。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Calibrating: turn the module slowly about every axis.</source>
        <translation>正在校准：请绕每个轴缓慢转动模块。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The device did not answer CONFIG MCAL START: its firmware is older than 1.7.0 or the link is down.</source>
        <translation>设备未应答 CONFIG MCAL START：其固件版本低于 1.7.0，或链路已断开。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The device refused CONFIG MCAL START (%1): it may have no magnetometer.</source>
        <translation>设备拒绝了 CONFIG MCAL START（%1）：设备可能没有磁力计。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The device stopped answering %1 (%2 times in a row).</source>
        <translation>设备已连续 %2 次未应答 %1。</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>LOG MAGCONFIG gave no MB line.</source>
        <translation>LOG MAGCONFIG 未返回 MB 行。</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+5"/>
        <source>LOG MAGCONFIG gave an unreadable MB line: %1</source>
        <translation>LOG MAGCONFIG 返回的 MB 行无法解析：%1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The device calibrated itself: bias %1, %2, %3 µT.</source>
        <translation>设备已自行完成校准：偏置 %1, %2, %3 µT。</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>LOG MCAL STAT gave no STAT line.</source>
        <translation>LOG MCAL STAT 未返回 STAT 行。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The device is idle: the calibration stopped (was the device restarted?). Start again.</source>
        <translation>设备处于空闲状态：校准已停止（设备是否重启过？）。请重新开始。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Calibrating (%1 %): keep turning the module slowly about every axis.</source>
        <translation>正在校准（%1 %）：请继续绕每个轴缓慢转动模块。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Verifying the result: hold the module still.</source>
        <translation>正在验证结果：请保持模块静止。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The device reports the calibration done.</source>
        <translation>设备报告校准完成。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The device reports the calibration failed (STAT=4).</source>
        <translation>设备报告校准失败（STAT=4）。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>LOG MCAL STAT gave an unknown state %1.</source>
        <translation>LOG MCAL STAT 返回了未知状态 %1。</translation>
    </message>
</context>
<context>
    <name>MagCalResult</name>
    <message>
        <location filename="../core/calib/mag_cal_result.cpp" line="+71"/>
        <source>Pass</source>
        <translation>通过</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Warning</source>
        <translation>警告</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Fail</source>
        <translation>失败</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Refused</source>
        <translation>已拒绝</translation>
    </message>
</context>
<context>
    <name>MagCalibrator</name>
    <message>
        <location filename="../core/calib/mag_calibrator.cpp" line="+90"/>
        <source>Only %1 usable samples; a full calibration needs at least %2. Keep turning the module slowly.</source>
        <translation>仅有 %1 个可用样本；完整校准至少需要 %2 个。请继续缓慢转动模块。</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>The samples lie in one plane (the module turned about one axis only), so a full 3-D calibration cannot be computed. Turn the module about its other axes too, or use the 2-D (planar) calibration, which is valid for level operation only.</source>
        <translation>样本位于同一平面内（模块只绕一个轴转动），因此无法计算完整的三维校准。请同时绕模块的其他轴转动，或使用二维（平面）校准，但它仅适用于水平工作。</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Only %1 % of the field directions are covered (at least %2 % are needed before a fit is tried). %3.</source>
        <translation>仅覆盖了 %1 % 的磁场方向（尝试拟合前至少需要 %2 %）。%3。</translation>
    </message>
    <message>
        <location line="+6"/>
        <location line="+9"/>
        <location line="+217"/>
        <source>A hard-iron-only fit (soft iron kept from before) is possible.</source>
        <translation>可以只拟合硬磁（沿用之前的软磁参数）。</translation>
    </message>
    <message>
        <location line="-220"/>
        <source>No ellipsoid fits these samples, which cover only part of the sphere. %1, then fit again.</source>
        <translation>这些样本只覆盖了球面的一部分，没有椭球能拟合它们。%1，然后重新拟合。</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>The samples do not describe an ellipsoid (strong interference or a moving magnet nearby). Move away from iron and electronics and calibrate again.</source>
        <translation>样本不构成椭球（存在强干扰或附近有移动的磁体）。请远离铁磁物体和电子设备后重新校准。</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Only %1 usable samples; the hard-iron fit needs at least %2.</source>
        <translation>仅有 %1 个可用样本；硬磁拟合至少需要 %2 个。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The samples are too close to a plane (eigenvalue ratio %1, at most %2) even for a hard-iron fit. Tilt the module more while turning it.</source>
        <translation>样本过于接近一个平面（特征值比 %1，最大 %2），连硬磁拟合也无法进行。转动时请让模块倾斜得更多。</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>The hard-iron fit found no solution: check that the samples come from the magnetometer in µT.</source>
        <translation>硬铁拟合无解：请检查样本是否来自磁力计且单位为 µT。</translation>
    </message>
    <message>
        <location line="+97"/>
        <source>field strength %1 µT is not the earth&apos;s field (%2..%3 µT)</source>
        <translation>磁场强度 %1 µT 不是地磁场（%2..%3 µT）</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>the predicted heading error of a level module, %1 deg, is above %2 deg (hard iron +-%3 µT)</source>
        <translation>模块水平时的预测航向误差 %1 deg 超过 %2 deg（硬铁 +-%3 µT）</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the heading error of a level module stays below %1 deg only 19 times in 20 (over %2 deg)</source>
        <translation>模块水平时的航向误差只有 20 次中 19 次低于 %1 deg（超过 %2 deg）</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>field strength %1 µT is outside the normal %2..%3 µT: move away from magnetic objects</source>
        <translation>磁场强度 %1 µT 超出正常范围 %2..%3 µT：请远离磁性物体</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>hard iron %1 µT is large (over 1.5 times the field): the sensor may saturate</source>
        <translation>硬铁 %1 µT 过大（超过磁场的 1.5 倍）：传感器可能饱和</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>field strength %1 µT differs from the expected %2 µT by more than 15 %</source>
        <translation>磁场强度 %1 µT 与预期的 %2 µT 相差超过 15 %</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>The data cannot give an accurate calibration: the predicted heading error of a level module is %1 deg, at most %2 deg is accepted (hard iron +-%3 µT, soft iron +-%4 %).</source>
        <translation>这些数据无法给出准确的校准：模块水平时的预测航向误差为 %1 deg，最多只接受 %2 deg（硬铁 +-%3 µT，软铁 +-%4 %）。</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>The directions are covered, but there are too few samples or they scatter too much (%1 µT RMS about the fit): collect more, turning slowly and evenly, away from iron and electronics.</source>
        <translation>方向已覆盖，但样本太少或离散过大（相对拟合 %1 µT RMS）：请远离铁器和电子设备，缓慢均匀地旋转，采集更多样本。</translation>
    </message>
    <message>
        <location line="-145"/>
        <source>Only %1 usable samples; the 2-D fit needs at least %2. Turn the module a full circle.</source>
        <translation>仅有 %1 个可用样本；二维拟合至少需要 %2 个。请将模块转动一整圈。</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>The horizontal samples do not describe an ellipse: turn the module one full, even circle.</source>
        <translation>水平方向的样本不构成椭圆：请将模块匀速转动一整圈。</translation>
    </message>
    <message>
        <location line="+47"/>
        <location line="+17"/>
        <source>fit error %1 % is above %2 %</source>
        <translation>拟合误差 %1 % 高于 %2 %</translation>
    </message>
    <message>
        <location line="-12"/>
        <source>soft-iron scale %1..%2 is outside %3..%4 (a magnet or iron part very close to the module)</source>
        <translation>软磁比例 %1..%2 超出 %3..%4（模块附近很近处有磁体或铁质部件）</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>only %1 % of the directions are covered</source>
        <translation>方向覆盖率仅为 %1 %</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1 of %2 samples were disturbed and set aside</source>
        <translation>%2 个样本中有 %1 个受到干扰，已剔除</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>2-D calibration: valid for level operation only; the vertical offset is unknown</source>
        <translation>二维校准：仅适用于水平工作；垂直方向偏移未知</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>2-D calibration: valid for level operation only</source>
        <translation>二维校准：仅适用于水平工作</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Calibration failed: %1.</source>
        <translation>校准失败：%1。</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>The data cannot give an accurate calibration: the fit&apos;s parameters are not determined by these samples.</source>
        <translation>这些数据无法给出准确的校准：这些样本确定不了拟合参数。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Part of the sphere is missing (a gap of %1 deg). %2, then fit again.</source>
        <translation>球面缺少一部分（空缺 %1 deg）。%2，然后重新拟合。</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Usable with care: %1.</source>
        <translation>可用但需谨慎：%1。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Good calibration: predicted heading error %1 deg (level module), fit error %2 %, %3 % of the directions covered.</source>
        <translation>校准良好：预测航向误差 %1 deg（水平放置），拟合误差 %2 %，覆盖了 %3 % 的方向。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Good calibration: fit error %1 %, %2 % of the directions covered.</source>
        <translation>校准良好：拟合误差 %1 %，方向覆盖率 %2 %。</translation>
    </message>
</context>
<context>
    <name>MagEnvironmentCheck</name>
    <message>
        <location filename="../core/calib/mag_environment_check.cpp" line="+57"/>
        <source>Hold the module at the calibration spot and turn it slowly to a few orientations.</source>
        <translation>将模块放在校准位置，缓慢转动到几个不同姿态。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The field is %1 µT (normal: %2..%3 µT) and varies by %4 µT between orientations: you can calibrate here.</source>
        <translation>磁场为 %1 µT（正常：%2..%3 µT），不同朝向之间变化 %4 µT：可以在此校准。</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The field is %1 µT, outside the normal %2..%3 µT: a strongly magnetic object is near. Move away from it, or choose another place.</source>
        <translation>磁场为 %1 µT，超出正常范围 %2..%3 µT：附近有强磁性物体。请远离它，或更换位置。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The field strength varies by %1 µT between orientations (more than %2 µT): there is spatial interference here. Choose another place (outdoors, away from buildings and vehicles), or use 6-axis mode.</source>
        <translation>不同朝向之间的磁场强度变化 %1 µT（超过 %2 µT）：此处存在空间磁场干扰。请更换位置（室外，远离建筑物和车辆），或改用 6 轴模式。</translation>
    </message>
</context>
<context>
    <name>MagEnvironmentJudge</name>
    <message>
        <location filename="../core/calib/mag_environment_judge.cpp" line="+166"/>
        <source>|B| changed by %1 µT while the module was still: something near it moves or switches (a magnet, a motor, a current). Remove it or choose another place.</source>
        <translation>模块静止时 |B| 变化了 %1 µT：附近有东西在移动或通断（磁铁、电机、电流）。请移走它或换一个地方。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Turn the module slowly to many orientations at the calibration spot: the field has pointed into %1 % of the sphere so far. The raw |B| (%2 µT now) includes the module&apos;s own iron, which the calibration removes, so it is not judged by itself.</source>
        <translation>请在校准位置把模块缓慢转到多个朝向：目前磁场已指向球面的 %1 %。原始 |B|（现在 %2 µT）包含模块自身的铁磁干扰，校准会将其去除，因此不单独据此判断。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>So far the field here is about %1 µT once the module&apos;s own iron (%2 µT) is taken out. Keep turning (%3 % of the sphere) for the full check.</source>
        <translation>去除模块自身的铁磁干扰（%2 µT）后，此处磁场目前约为 %1 µT。请继续转动（已覆盖球面的 %3 %）以完成完整检查。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The field here is %1 µT once the module&apos;s own iron (%2 µT) is taken out: within the Earth&apos;s %3..%4 µT, and the same in every orientation within %5 µT. You can calibrate here.</source>
        <translation>去除模块自身的铁磁干扰（%2 µT）后，此处磁场为 %1 µT：在地磁场的 %3..%4 µT 范围内，且各朝向之间相差不超过 %5 µT。可以在此校准。</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The field here is %1 µT once the module&apos;s own iron (%2 µT) is taken out, outside the Earth&apos;s %3..%4 µT: a magnetic object or a steel structure is near. Move away from it, or choose another place.</source>
        <translation>去除模块自身的铁磁干扰（%2 µT）后，此处磁场为 %1 µT，超出地磁场的 %3..%4 µT：附近有磁性物体或钢结构。请远离它，或换一个地方。</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Once the module&apos;s own iron is taken out, the field still differs by %1 µT between orientations (more than %2 µT): it is not uniform here. Choose another place (outdoors, away from buildings and vehicles), or use 6-axis mode.</source>
        <translation>去除模块自身的铁磁干扰后，各朝向之间的磁场仍相差 %1 µT（超过 %2 µT）：此处磁场不均匀。请换一个地方（室外，远离建筑物和车辆），或使用 6 轴模式。</translation>
    </message>
</context>
<context>
    <name>MagnetometerFile</name>
    <message>
        <location filename="../core/record/magnetometer_file.cpp" line="+59"/>
        <source>%1 holds no magnetometer samples in µT (a %2): record the module&apos;s output with its magnetometer (HI91, HI81 or HI83)</source>
        <translation>%1 中没有以 µT 为单位的磁力计样本（%2）：请录制包含磁力计的模块输出（HI91、HI81 或 HI83）</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>line %1 is not a JSON object: %2</source>
        <translation>第 %1 行不是 JSON 对象：%2</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>line %1, key mag: three numbers [x, y, z] in µT are needed</source>
        <translation>第 %1 行，键 mag：需要三个以 µT 为单位的数 [x, y, z]</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>more than %1 samples</source>
        <translation>超过 %1 个样本</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+28"/>
        <source>the file holds %1 devices (%2): choose one with --device NAME</source>
        <translation>文件包含 %1 个设备（%2）：请用 --device NAME 选择一个</translation>
    </message>
    <message>
        <location line="-24"/>
        <location line="+30"/>
        <source>the file has no device %1; its devices: %2</source>
        <translation>文件中没有设备 %1；其设备：%2</translation>
    </message>
    <message>
        <location line="-28"/>
        <source>no line has a key mag (the magnetometer, µT)</source>
        <translation>没有任何一行包含键 mag（磁力计，µT）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 lines without a magnetometer passed over</source>
        <translation>已跳过 %1 行无磁力计数据的行</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>--device %1: the file has no device column</source>
        <translation>--device %1：文件中没有 device 列</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 rows without a magnetometer passed over</source>
        <translation>已跳过 %1 行无磁力计数据的行</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>cannot read %1: %2</source>
        <translation>无法读取 %1：%2</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1 is larger than %2 MB; split it</source>
        <translation>%1 大于 %2 MB；请将其拆分</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
</context>
<context>
    <name>McapRecording</name>
    <message>
        <location filename="../core/capture/mcap_recording.cpp" line="+97"/>
        <source>Cannot write %1: %2</source>
        <translation>无法写入 %1：%2</translation>
    </message>
</context>
<context>
    <name>McapRepair</name>
    <message>
        <location filename="../core/format/mcap/mcap_repair.cpp" line="+181"/>
        <source>%1 cannot be read: %2</source>
        <translation>无法读取 %1：%2</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 is not an MCAP file (it does not start with MCAP&apos;s magic bytes).</source>
        <translation>%1 不是 MCAP 文件（开头不是 MCAP 的标识字节）。</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>This is not an MCAP file (it does not start with MCAP&apos;s magic bytes).</source>
        <translation>这不是 MCAP 文件（开头不是 MCAP 的标识字节）。</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>Cannot write %1: %2</source>
        <translation>无法写入 %1：%2</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The file cannot be read from its start again.</source>
        <translation>无法从头重新读取该文件。</translation>
    </message>
    <message>
        <location line="+25"/>
        <location line="+10"/>
        <source>Writing %1 failed: %2</source>
        <translation>写入 %1 失败：%2</translation>
    </message>
</context>
<context>
    <name>ModbusSimulator</name>
    <message>
        <location filename="../core/sim/modbus_simulator.cpp" line="+45"/>
        <source>The simulated Modbus device could not open %1: %2</source>
        <translation>模拟 Modbus 设备无法打开 %1：%2</translation>
    </message>
</context>
<context>
    <name>ModbusUi</name>
    <message>
        <location filename="../ui/families/modbus_ui.cpp" line="+19"/>
        <source>Simulated HEC495 (Modbus)</source>
        <translation>模拟 HEC495（Modbus）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Simulated HI14 (Modbus)</source>
        <translation>模拟 HI14（Modbus）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1, Modbus node %2</source>
        <translation>%1，Modbus 节点 %2</translation>
    </message>
</context>
<context>
    <name>MotionCheck</name>
    <message>
        <location filename="../core/calib/motion_check.cpp" line="+87"/>
        <source>the module moved: Allan deviation needs a still recording</source>
        <translation>模块移动过：阿伦方差需要静止状态下的记录</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>gyro std dev %1 °/s, a module at rest stays below %2 °/s</source>
        <translation>陀螺仪标准差 %1 °/s，静止的模块低于 %2 °/s</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>its rate changed by %1 °/s between 1-s windows: it was turned</source>
        <translation>其角速度在 1 秒窗口之间变化了 %1 °/s：模块被转动过</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>it turned steadily at %1 °/s; a gyro&apos;s bias stays below %2 °/s</source>
        <translation>模块以 %1 °/s 匀速转动；陀螺仪零偏低于 %2 °/s</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>its acceleration changed by %1 G between 1-s windows: it was tilted or pushed</source>
        <translation>其加速度在 1 秒窗口之间变化了 %1 G：模块被倾斜或推动过</translation>
    </message>
</context>
<context>
    <name>MountingChoice</name>
    <message>
        <location filename="../core/settings/mounting_choice.cpp" line="+69"/>
        <source>IMU X and IMU Y cannot both point %1 / %2: they must be at right angles</source>
        <translation>IMU X 朝%1、IMU Y 朝%2 不可行：两轴必须相互垂直</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>IMU X %1, IMU Y %2, IMU Z %3 is left-handed or not at right angles: with X %1 and Y %2, Z points %4</source>
        <translation>IMU X 朝%1、IMU Y 朝%2、IMU Z 朝%3 构成左手系或各轴不相互垂直：X 朝%1、Y 朝%2 时，Z 应朝%4</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>no URFR code for this mounting</source>
        <translation>此安装方式没有对应的 URFR 代码</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>right</source>
        <translation>右</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>left</source>
        <translation>左</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>forward</source>
        <translation>前</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>back</source>
        <translation>后</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>up</source>
        <translation>上</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>down</source>
        <translation>下</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>IMU X %1, IMU Y %2, IMU Z %3</source>
        <translation>IMU X 朝%1，IMU Y 朝%2，IMU Z 朝%3</translation>
    </message>
</context>
<context>
    <name>PtyBridge</name>
    <message>
        <location filename="../core/sim/pty_bridge.cpp" line="+29"/>
        <source>Cannot open a pseudo-terminal: %1</source>
        <translation>无法打开伪终端：%1</translation>
    </message>
    <message>
        <location line="+65"/>
        <source>Cannot create a pipe: %1</source>
        <translation>无法创建管道：%1</translation>
    </message>
</context>
<context>
    <name>PtySimulator</name>
    <message>
        <location filename="../core/sim/pty_simulator.cpp" line="+328"/>
        <source>Cannot open a pseudo-terminal: %1</source>
        <translation>无法打开伪终端：%1</translation>
    </message>
</context>
<context>
    <name>QtCanFrameLink</name>
    <message>
        <location filename="../core/firmware/qt_can_frame_link.cpp" line="+31"/>
        <source>the CAN plugin &quot;%1&quot; is not installed (available: %2)</source>
        <translation>未安装 CAN 插件“%1”（可用插件：%2）</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>cannot create the CAN device %1:%2: %3</source>
        <translation>无法创建 CAN 设备 %1:%2：%3</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>cannot open the CAN device %1:%2: %3. Check the interface name and that it is up</source>
        <translation>无法打开 CAN 设备 %1:%2：%3。请检查接口名称以及接口是否已启用</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>the CAN device %1:%2 did not connect within %3 ms: %4</source>
        <translation>CAN 设备 %1:%2 在 %3 ms 内未连接：%4</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>the CAN device %1:%2 is not connected (%3); check the cable and the adapter</source>
        <translation>CAN 设备 %1:%2 未连接（%3）；请检查线缆和适配器</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>closed</source>
        <translation>已关闭</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>sending a CAN frame failed: %1</source>
        <translation>发送 CAN 帧失败：%1</translation>
    </message>
</context>
<context>
    <name>RegisterMap</name>
    <message>
        <location filename="../core/protocol/modbus/register_map.cpp" line="+19"/>
        <source>Control: 0 saves the configuration to flash, 1 restores factory settings, 0xFF resets</source>
        <translation>控制：0 将配置保存到闪存，1 恢复出厂设置，0xFF 复位</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Baud rate code: 0=4800 1=9600 2=19200 3=38400 4=57600 5=115200 6=230400 7=460800 8=921600</source>
        <translation>波特率代码：0=4800 1=9600 2=19200 3=38400 4=57600 5=115200 6=230400 7=460800 8=921600</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Modbus node ID, 1-128; takes effect at once</source>
        <translation>Modbus 节点 ID，1-128；立即生效</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>0: 6-axis (relative heading, 0 at power-up), 1: 9-axis (magnetic, absolute heading)</source>
        <translation>0：6 轴（相对航向角，上电时为 0），1：9 轴（地磁，绝对航向角）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Acceleration X</source>
        <translation>加速度 X</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Acceleration Y</source>
        <translation>加速度 Y</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Acceleration Z</source>
        <translation>加速度 Z</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Angular rate X</source>
        <translation>角速度 X</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Angular rate Y</source>
        <translation>角速度 Y</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Angular rate Z</source>
        <translation>角速度 Z</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Magnetic field X</source>
        <translation>磁场 X</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Magnetic field Y</source>
        <translation>磁场 Y</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Magnetic field Z</source>
        <translation>磁场 Z</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Roll (R_H high word, R_L low word)</source>
        <translation>横滚角（R_H 高字，R_L 低字）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Pitch (P_H high word, P_L low word)</source>
        <translation>俯仰角（P_H 高字，P_L 低字）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Yaw (Y_H high word, Y_L low word)</source>
        <translation>航向角（Y_H 高字，Y_L 低字）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Temperature</source>
        <translation>温度</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Pressure (PRS_H high word, PRS_L low word)</source>
        <translation>气压（PRS_H 高字，PRS_L 低字）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Quaternion W</source>
        <translation>四元数 W</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Quaternion X</source>
        <translation>四元数 X</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Quaternion Y</source>
        <translation>四元数 Y</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Quaternion Z</source>
        <translation>四元数 Z</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Inclinometer X angle (dual axis: +-180; single axis: 0-360)</source>
        <translation>倾角仪 X 轴角度（双轴：+-180；单轴：0-360）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Inclinometer Y angle (dual axis: +-90; single axis: reserved)</source>
        <translation>倾角仪 Y 轴角度（双轴：+-90；单轴：保留）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ship heave displacement</source>
        <translation>船舶垂荡位移</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ship heave period</source>
        <translation>船舶垂荡周期</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Device name (ASCII, 8 registers)</source>
        <translation>设备名称（ASCII，8 个寄存器）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Software version (152 = V1.52)</source>
        <translation>软件版本（152 = V1.52）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Bootloader version (107 = V1.07)</source>
        <translation>引导程序版本（107 = V1.07）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Unique serial number (4 registers)</source>
        <translation>唯一序列号（4 个寄存器）</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+2"/>
        <source>Auto-level: 3 levels once when pitch and roll are within 15 deg of 0/0 or 0/180, 5 cancels (the register table, which calls other values invalid). The manual&apos;s worked example writes 2 to level; ImuDesk accepts 2 and 3, and its own level action sends 2, byte for byte as the example</source>
        <translation>自动调平：3 在俯仰角和横滚角与 0/0 或 0/180 相差 15 deg 以内时执行一次调平，5 取消（寄存器表，其中其他值均为无效）。手册示例写入 2 进行调平；ImuDesk 接受 2 和 3，其自身的调平操作发送 2，与示例逐字节一致</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Mounting: the URFR code (0x18 = 024 horizontal, 0x2B = 043, 0x34 = 052, 0x208 = 520, 0x1A5 = 421)</source>
        <translation>安装方式：URFR 代码（0x18 = 024 水平，0x2B = 043，0x34 = 052，0x208 = 520，0x1A5 = 421）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Mounting: 0 horizontal, 1 Y axis down, 2 Y axis up, 3 X axis up, 4 X axis down</source>
        <translation>安装方式：0 水平，1 Y 轴朝下，2 Y 轴朝上，3 X 轴朝上，4 X 轴朝下</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>Pitch (X axis) angle, float</source>
        <translation>俯仰角（X 轴），浮点数</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Roll (Y axis) angle, float</source>
        <translation>横滚角（Y 轴），浮点数</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Heading (Z axis) angle, float</source>
        <translation>航向角（Z 轴），浮点数</translation>
    </message>
</context>
<context>
    <name>ReplayUi</name>
    <message>
        <location filename="../ui/families/replay_ui.cpp" line="+18"/>
        <source>Replay of %1</source>
        <translation>回放 %1</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Replay</source>
        <translation>回放</translation>
    </message>
</context>
<context>
    <name>Reply</name>
    <message>
        <location filename="../core/protocol/witlink/reply.cpp" line="+149"/>
        <source>no error</source>
        <translation>无错误</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a reply command that the HEC495 manual does not list</source>
        <translation>HEC495 手册中未列出的应答指令</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a data field of the wrong length for this reply</source>
        <translation>数据字段长度与此应答不符</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a BCD value with a digit above 9 or a bad sign nibble</source>
        <translation>BCD 数值中有大于 9 的数字或符号半字节错误</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a status byte that is neither 00 (success) nor FF (failure)</source>
        <translation>状态字节既不是 00（成功）也不是 FF（失败）</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1: invalid reply (%2)</source>
        <translation>%1：应答无效（%2）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: %2 deg</source>
        <translation>%1：%2 deg</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>pitch %1 deg, roll %2 deg, heading %3 deg</source>
        <translation>俯仰角 %1 deg，横滚角 %2 deg，航向角 %3 deg</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>pitch %1 deg, roll %2 deg, heading %3 deg, time %4 ms</source>
        <translation>俯仰角 %1 deg，横滚角 %2 deg，航向角 %3 deg，时间 %4 ms</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>declination %1 deg</source>
        <translation>磁偏角 %1 deg</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1: success</source>
        <translation>%1：成功</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1: the device reported failure</source>
        <translation>%1：设备报告失败</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>calibration saved: fit error %1, %2 points</source>
        <translation>校准已保存：拟合误差 %1，%2 个点</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>calibration point collected: %1 points</source>
        <translation>已采集校准点：共 %1 个点</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>address %1</source>
        <translation>地址 %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>unknown reply</source>
        <translation>未知应答</translation>
    </message>
</context>
<context>
    <name>SDO</name>
    <message>
        <location filename="../core/protocol/can/sdo.cpp" line="+11"/>
        <source>toggle bit not alternated</source>
        <translation>翻转位未交替</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>SDO protocol timed out</source>
        <translation>SDO 协议超时</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>command specifier not valid or unknown</source>
        <translation>指令说明符无效或未知</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>out of memory</source>
        <translation>内存不足</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unsupported access to an object</source>
        <translation>不支持对该对象的访问</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>attempt to read a write-only object</source>
        <translation>试图读取只写对象</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>attempt to write a read-only object</source>
        <translation>试图写入只读对象</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>object does not exist in the object dictionary</source>
        <translation>对象字典中不存在该对象</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>data type does not match, length of service parameter does not match</source>
        <translation>数据类型不匹配，服务参数长度不匹配</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>sub-index does not exist</source>
        <translation>子索引不存在</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>invalid value for parameter</source>
        <translation>参数值无效</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>value of parameter written too high</source>
        <translation>写入的参数值过大</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>value of parameter written too low</source>
        <translation>写入的参数值过小</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>general error</source>
        <translation>一般错误</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>data cannot be transferred or stored to the application</source>
        <translation>数据无法传输或存储到应用</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>data cannot be transferred because of the present device state</source>
        <translation>由于设备当前状态，数据无法传输</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>abort code 0x%1</source>
        <translation>中止代码 0x%1</translation>
    </message>
    <message>
        <location line="+122"/>
        <source>SDO write %1 = %2 (%3 bytes)</source>
        <translation>SDO 写入 %1 = %2（%3 字节）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>SDO segmented write %1, %2 bytes</source>
        <translation>SDO 分段写入 %1，%2 字节</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>SDO segment</source>
        <translation>SDO 分段</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>SDO write %1 confirmed</source>
        <translation>SDO 写入 %1 已确认</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>SDO segment confirmed</source>
        <translation>SDO 分段已确认</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>SDO read %1</source>
        <translation>SDO 读取 %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>SDO read %1 -&gt; %2</source>
        <translation>SDO 读取 %1 -&gt; %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>SDO read %1: segmented, %2 bytes</source>
        <translation>SDO 读取 %1：分段传输，%2 字节</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>SDO abort %1: %2</source>
        <translation>SDO 中止 %1：%2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>SDO command 0x%1</source>
        <translation>SDO 指令 0x%1</translation>
    </message>
    <message>
        <location filename="../core/protocol/can/sdo_segmented_download.cpp" line="+60"/>
        <source>the device aborted the transfer: %1</source>
        <translation>设备中止了传输：%1</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>the device confirmed a segment with the wrong toggle bit</source>
        <translation>设备确认分段时翻转位错误</translation>
    </message>
</context>
<context>
    <name>SampleAnalyzer</name>
    <message>
        <location filename="../core/record/sample_analyzer.cpp" line="+157"/>
        <source>cannot judge: the recording is too short</source>
        <translation>无法判断：记录太短</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>%1 frames over %2 s; the random walk is read at τ = %3 s, which needs at least %4 s of a still module (%5 s for 10 % uncertainty)</source>
        <translation>%2 s 内共 %1 帧；随机游走取自 τ = %3 s，至少需要模块静止 %4 s 的数据（不确定度 10 % 需要 %5 s）</translation>
    </message>
</context>
<context>
    <name>SampleCsv</name>
    <message>
        <location filename="../core/calib/sample_csv.cpp" line="+26"/>
        <source>line %1 is longer than %2 characters</source>
        <translation>第 %1 行超过 %2 个字符</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>line %1 has more than %2 columns</source>
        <translation>第 %1 行超过 %2 列</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>line %1: the header has an empty column name</source>
        <translation>第 %1 行：表头中有空列名</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+86"/>
        <source>line %1: a header row of column names is required (e.g. mag_x,mag_y,mag_z)</source>
        <translation>第 %1 行：需要一行列名作为表头（例如 mag_x,mag_y,mag_z）</translation>
    </message>
    <message>
        <location line="-78"/>
        <location line="+89"/>
        <source>line %1 has %2 values, the header has %3 columns</source>
        <translation>第 %1 行有 %2 个值，表头有 %3 列</translation>
    </message>
    <message>
        <location line="-84"/>
        <location line="+105"/>
        <source>more than %1 rows</source>
        <translation>超过 %1 行</translation>
    </message>
    <message>
        <location line="-98"/>
        <location line="+106"/>
        <source>line %1, column %2: &apos;%3&apos; is not a number</source>
        <translation>第 %1 行第 %2 列：“%3”不是数字</translation>
    </message>
    <message>
        <location line="-94"/>
        <location line="+106"/>
        <source>the file is empty: a header row and samples are needed</source>
        <translation>文件为空：需要表头行和样本数据</translation>
    </message>
    <message>
        <location line="-60"/>
        <source>line %1: the column %2 is missing (needed: %3); the header has: %4</source>
        <translation>第 %1 行：缺少列 %2（需要：%3）；表头为：%4</translation>
    </message>
    <message>
        <location line="+92"/>
        <source>the columns mag_x, mag_y and mag_z (µT) are needed; the header has: %1</source>
        <translation>需要 mag_x、mag_y 和 mag_z 列（单位 µT）；表头中只有：%1</translation>
    </message>
</context>
<context>
    <name>SampleFile</name>
    <message>
        <location filename="../core/record/sample_file.cpp" line="+53"/>
        <source>--device chooses a device of a session: %1 is not one</source>
        <translation>--device 用于选择会话中的设备：%1 不是会话</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1 is a folder without session.json: give a file, or a recorded session&apos;s folder</source>
        <translation>%1 是不含 session.json 的文件夹：请给出一个文件，或已录制会话的文件夹</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>the session %1 has no device %2; its devices: %3</source>
        <translation>会话 %1 中没有设备 %2；其设备：%3</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the session %1 holds %2 devices (%3): choose one with --device NAME</source>
        <translation>会话 %1 包含 %2 个设备（%3）：请用 --device NAME 选择一个</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>session</source>
        <translation>会话</translation>
    </message>
</context>
<context>
    <name>SerialByteLink</name>
    <message>
        <location filename="../core/firmware/serial_byte_link.cpp" line="+62"/>
        <location line="+24"/>
        <source>the port %1 is not open</source>
        <translation>串口 %1 未打开</translation>
    </message>
    <message>
        <location line="-18"/>
        <source>writing to %1 failed: %2</source>
        <translation>向 %1 写入失败：%2</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>writing to %1 stalled: %2</source>
        <translation>向 %1 写入停滞：%2</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>reading from %1 failed: %2 (was the device unplugged?)</source>
        <translation>从 %1 读取失败：%2（设备是否已拔出？）</translation>
    </message>
</context>
<context>
    <name>SessionExporter</name>
    <message>
        <location filename="../core/record/session_exporter.cpp" line="+184"/>
        <source>A session of several devices exports to tidy CSV, JSON Lines, MCAP or MATLAB; the vendor&apos;s layout has one device per file (export each capture on its own for it).</source>
        <translation>多设备会话可导出为整齐 CSV、JSON Lines、MCAP 或 MATLAB；厂商格式每个文件只含一台设备（如需该格式，请逐个导出各记录）。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>A grid or trigger pairs are written as tidy CSV (--format csv).</source>
        <translation>网格或触发配对以整洁 CSV 写出（--format csv）。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>No output file was given.</source>
        <translation>未指定输出文件。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>A grid of at least 0.01 ms, or a pulse rate up to 10 kHz, not both.</source>
        <translation>网格至少 0.01 ms，或脉冲频率不超过 10 kHz，二者不可同时指定。</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Device %1: %2</source>
        <translation>设备 %1：%2</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Device %1 dropped out during the recording (session.json says when); its data ends there.</source>
        <translation>设备 %1 在录制期间掉线（时间见 session.json）；其数据到此为止。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The session holds no device.</source>
        <translation>该会话中没有设备。</translation>
    </message>
    <message>
        <location line="-128"/>
        <location line="+141"/>
        <source>Cannot write %1: %2</source>
        <translation>无法写入 %1：%2</translation>
    </message>
    <message>
        <location line="-108"/>
        <location line="+40"/>
        <location line="+104"/>
        <location line="+85"/>
        <source>Export cancelled.</source>
        <translation>导出已取消。</translation>
    </message>
    <message>
        <location line="-26"/>
        <source>%1 frames of devices whose clock never aligned have no pulse index.</source>
        <translation>时钟从未对齐的设备有 %1 帧没有脉冲序号。</translation>
    </message>
    <message>
        <location line="+88"/>
        <source>Device %1 (%2): nothing in its capture that ImuDesk decodes offline (Modbus captures are not decoded yet); it is left out.</source>
        <translation>设备 %1（%2）：其记录中没有 ImuDesk 可离线解码的内容（Modbus 记录尚不能解码），已略去。</translation>
    </message>
    <message>
        <location line="-285"/>
        <location line="+290"/>
        <source>Writing %1 failed: %2. Free some space or choose another place.</source>
        <translation>写入 %1 失败：%2。请释放一些空间或选择其他位置。</translation>
    </message>
</context>
<context>
    <name>SettingCatalog</name>
    <message>
        <location filename="../core/settings/setting_catalog.cpp" line="+22"/>
        <source>Output of this message on this port: off, every period (ONTIME 0.001 s = 1 kHz .. 1 s = 1 Hz) or on each SYNC_IN/PPS rising edge (ONMARK 1).</source>
        <translation>此消息在本串口上的输出：关闭、按周期输出（ONTIME 0.001 s = 1 kHz .. 1 s = 1 Hz），或在每个 SYNC_IN/PPS 上升沿输出（ONMARK 1）。</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Serial baud rate</source>
        <translation>串口波特率</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>SERIALCONFIG: the UART switches at once; ImuDesk follows and confirms with LOG VERSION. v1.7.1: 4800 .. 921600; v1.6.6: 9600, 115200, 256000, 460800, 921600.</source>
        <translation>SERIALCONFIG：UART 立即切换；ImuDesk 随之切换，并用 LOG VERSION 确认。v1.7.1：4800 .. 921600；v1.6.6：9600、115200、256000、460800、921600。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Data output</source>
        <translation>数据输出</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>LOG ENABLE / LOG DISABLE: all data frames on or off. Output is enabled again after every start.</source>
        <translation>LOG ENABLE / LOG DISABLE：打开或关闭全部数据帧。每次启动后输出都会重新打开。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>HI91 output (float IMU frame)</source>
        <translation>HI91 输出（浮点 IMU 帧）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>HI92 output (integer IMU frame)</source>
        <translation>HI92 输出（整型 IMU 帧）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>HI81 output (INS frame)</source>
        <translation>HI81 输出（INS 帧）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>HI83 output (variable frame)</source>
        <translation>HI83 输出（可变帧）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>NMEA GGA output</source>
        <translation>NMEA GGA 输出</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>NMEA RMC output</source>
        <translation>NMEA RMC 输出</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>NMEA SXT output</source>
        <translation>NMEA SXT 输出</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>HI83 fields (data_bitmap)</source>
        <translation>HI83 字段（data_bitmap）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>LOG HI83 MAP: one bit per data segment (bit 0 acc, 1 gyr, 2 mag, 3 Euler, 4 quaternion, 5 time us, 6 UTC, 7 pressure, ..., 25 filter update counters, 26 and 27 filter biases, 28 GNSS accuracy, 29 dual-antenna heading, 30 and 31 GNSS position and velocity; 20 to 24 are reserved); default 0x000000FF.</source>
        <translation>LOG HI83 MAP：每位对应一个数据段（位 0 加速度、1 角速度、2 磁场、3 欧拉角、4 四元数、5 时间 us、6 UTC、7 气压、……、25 滤波器量测更新计数、26 和 27 滤波器零偏、28 GNSS 精度、29 双天线航向、30 和 31 GNSS 位置与速度；20 至 24 保留）；默认 0x000000FF。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Working mode</source>
        <translation>工作模式</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CONFIG ATT MODE: 0 VRU (6-axis), 1 AHRS (9-axis, magnetometer aided; calibrate the magnetometer first, avoid near motors and indoors), 4 humanoid robot (v1.7.1).</source>
        <translation>CONFIG ATT MODE：0 VRU（6 轴），1 AHRS（9 轴，磁力计辅助；请先进行地磁校准，避免在电机附近和室内使用），4 人形机器人（v1.7.1）。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Mounting (URFR)</source>
        <translation>安装方式（URFR）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CONFIG IMU URFR: which sensor direction each user axis is (code ABC, 24 right-handed codes; 24 = X right, Y forward, Z up). Firmware below 1.7.1 takes the nine numbers of the matrix C as the manual&apos;s named mountings print it (X_U = C * X_B; 1,0,0,0,0,1,0,-1,0 is Y down).</source>
        <translation>CONFIG IMU URFR：每个用户轴对应传感器的哪个方向（代码 ABC，共 24 个右手系代码；24 = X 朝右、Y 朝前、Z 朝上）。低于 1.7.1 的固件使用矩阵 C 的九个数，与手册中各命名安装方式的示例一致（X_U = C * X_B；1,0,0,0,0,1,0,-1,0 为 Y 轴朝下）。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>World frame</source>
        <translation>世界坐标系</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CONFIG IMU COORD: 0 East-North-Up (ENU, default), 4 North-West-Up (NWU).</source>
        <translation>CONFIG IMU COORD：0 东北天（ENU，默认），4 北西天（NWU）。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>PMUX1 pin (SYNC_IN/PPS input)</source>
        <translation>PMUX1 引脚（SYNC_IN/PPS 输入）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PMUX2 pin (SOUT sync output)</source>
        <translation>PMUX2 引脚（SOUT 同步输出）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PMUX3 pin (status LED)</source>
        <translation>PMUX3 引脚（状态 LED）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>CONFIG PMUXn IOm: the IO pin that carries this function (defaults PMUX1 IO1, PMUX2 IO2, PMUX3 IO5). Not every IO is brought out on every product.</source>
        <translation>CONFIG PMUXn IOm：承担该功能的 IO 引脚（默认 PMUX1 IO1，PMUX2 IO2，PMUX3 IO5）。并非每款产品都引出了所有 IO。</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>SOUT divider</source>
        <translation>SOUT 分频</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CONFIG PMUX2 DIV: one SOUT pulse every N frames (1 .. 1000, default 1): at 100 Hz output, 5 gives 20 Hz pulses for a camera.</source>
        <translation>CONFIG PMUX2 DIV：每 N 帧输出一个 SOUT 脉冲（1 .. 1000，默认 1）：输出为 100 Hz 时，设为 5 可为相机提供 20 Hz 脉冲。</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Background magnetometer calibration</source>
        <translation>后台地磁校准</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CONFIG IMU_EN_MCAL (v1.6.6): 1 calibrates the magnetometer in the background (factory default), 0 stops it; SAVECONFIG keeps it.</source>
        <translation>CONFIG IMU_EN_MCAL（v1.6.6）：1 在后台进行地磁校准（出厂默认），0 停止；执行 SAVECONFIG 后保持。</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Heading reset</source>
        <translation>航向角清零</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Sets the current heading to 0. Keep the device still while it runs.</source>
        <translation>将当前航向角设为 0。执行期间请保持设备静止。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Relative level (zero pitch and roll)</source>
        <translation>相对调平（俯仰角和横滚角清零）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Makes the current pitch and roll the zero, whatever the tilt (no check). Keep the device still; ATT RST 5 undoes it; SAVECONFIG keeps it.</source>
        <translation>无论倾斜多少，都将当前俯仰角和横滚角设为零点（不作检查）。请保持设备静止；ATT RST 5 可撤销；执行 SAVECONFIG 后保持。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Automatic levelling</source>
        <translation>自动调平</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Only when nearly level: pitch and roll both below 5 deg levels to 0/0, pitch below 5 deg and roll near 180 deg levels to 0/180; otherwise refused (ERR). Keep the device still. Permanent: ATT RST 5 does not undo it, only a factory reset does.</source>
        <translation>仅在接近水平时可用：俯仰角和横滚角均小于 5 deg 时调平到 0/0，俯仰角小于 5 deg 且横滚角接近 180 deg 时调平到 0/180；否则拒绝执行（ERR）。请保持设备静止。永久生效：ATT RST 5 无法撤销，只有恢复出厂设置才能撤销。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Cancel relative level</source>
        <translation>取消相对调平</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Clears the relative pitch/roll zero of ATT RST 2 and returns to absolute angles.</source>
        <translation>清除 ATT RST 2 设定的俯仰角/横滚角相对零点，恢复为绝对角度。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Set heading (v1.6.6)</source>
        <translation>设置航向角（v1.6.6）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CONFIG YAW MODE DEG: MODE 1 sets the heading to DEG (absolute), MODE 0 adds DEG (relative); -180 .. 180 deg; at once, not saved. Value &quot;MODE,DEG&quot;, e.g. 1,16.</source>
        <translation>CONFIG YAW MODE DEG：MODE 1 将航向角设为 DEG（绝对），MODE 0 在当前航向角上加 DEG（相对）；-180 .. 180 deg；立即生效，不保存。取值格式为“MODE,DEG”，例如 1,16。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Save to flash</source>
        <translation>保存到闪存</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Saves every setting to flash so that it survives a reset.</source>
        <translation>将所有设置保存到闪存，复位后仍然有效。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Reboot</source>
        <translation>重启</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Resets the module (same as a power cycle): unsaved settings are lost, saved CONFIG settings take effect.</source>
        <translation>复位模块（等同于断电重启）：未保存的设置将丢失，已保存的 CONFIG 设置生效。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Factory reset</source>
        <translation>恢复出厂设置</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Restores the factory settings, saves them and resets: baud 115200, HI91 at 100 Hz, mounting 24, working mode, PMUX pins, output messages and ATT RST 3 levelling are all lost.</source>
        <translation>恢复出厂设置、保存并复位：波特率恢复为 115200，HI91 以 100 Hz 输出，安装方式恢复为 24；工作模式、PMUX 引脚、输出消息和 ATT RST 3 调平结果都将丢失。</translation>
    </message>
    <message>
        <location line="+69"/>
        <source>VRU (6-axis)</source>
        <translation>VRU（6 轴）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>AHRS (9-axis, magnetometer aided)</source>
        <translation>AHRS（9 轴，磁力计辅助）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Humanoid robot</source>
        <translation>人形机器人</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>East-North-Up (ENU)</source>
        <translation>东北天（ENU）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>North-West-Up (NWU)</source>
        <translation>北西天（NWU）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Off</source>
        <translation>关闭</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>On (factory default)</source>
        <translation>开启（出厂默认）</translation>
    </message>
    <message>
        <location line="+65"/>
        <location line="+10"/>
        <source>not in the manual for firmware %1</source>
        <translation>固件 %1 的手册中没有此项</translation>
    </message>
    <message>
        <location line="-8"/>
        <location line="+10"/>
        <source>%1 has no %2 (v1.7.1 feature table)</source>
        <translation>%1 不具备 %2 功能（v1.7.1 功能表）</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1=%2: %3</source>
        <translation>%1=%2：%3</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>a baud rate is a whole number</source>
        <translation>波特率必须是整数</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>firmware below 1.7.1 takes 9600, 115200, 256000, 460800 or 921600</source>
        <translation>低于 1.7.1 的固件支持 9600、115200、256000、460800 或 921600</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>supported rates are 4800, 9600, 19200, 38400, 57600, 115200, 230400, 256000, 460800 and 921600</source>
        <translation>支持的波特率为 4800、9600、19200、38400、57600、115200、230400、256000、460800 和 921600</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>use ENABLE or DISABLE</source>
        <translation>请使用 ENABLE 或 DISABLE</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>use a period in seconds (0.001 .. 1, 0 = off), ONMARK or OFF</source>
        <translation>请使用以秒为单位的周期（0.001 .. 1，0 = 关闭）、ONMARK 或 OFF</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>use a bitmap such as 0x000000FF</source>
        <translation>请使用位图，例如 0x000000FF</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>not one of the documented values</source>
        <translation>不是文档中列出的取值</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 (%2) is not available on this model or firmware</source>
        <translation>%1（%2）在此型号或固件上不可用</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>not one of the 24 right-handed URFR codes</source>
        <translation>不是 24 个右手系 URFR 代码之一</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the matrix is nine numbers C00,C01,...,C22</source>
        <translation>矩阵为九个数 C00,C01,...,C22</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>firmware 1.7.1 takes only the 24 URFR codes</source>
        <translation>固件 1.7.1 只接受 24 个 URFR 代码</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>use a pin IO1 .. IO%1</source>
        <translation>请使用引脚 IO1 .. IO%1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>use a whole number %1 .. %2</source>
        <translation>请使用 %1 .. %2 之间的整数</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>unknown setting kind</source>
        <translation>未知的设置类型</translation>
    </message>
    <message>
        <location line="+23"/>
        <location line="+43"/>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1 takes no value</source>
        <translation>%1 不需要取值</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>YAW needs MODE,DEG (MODE 0 relative or 1 absolute, DEG -180 .. 180), e.g. YAW=1,16</source>
        <translation>YAW 需要 MODE,DEG（MODE 0 为相对、1 为绝对，DEG 为 -180 .. 180），例如 YAW=1,16</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>YAW: %1</source>
        <translation>YAW：%1</translation>
    </message>
    <message>
        <location line="+11"/>
        <location line="+33"/>
        <source>off</source>
        <translation>关闭</translation>
    </message>
    <message>
        <location line="-31"/>
        <source>on SYNC_IN pulse (ONMARK 1)</source>
        <translation>SYNC_IN 脉冲触发（ONMARK 1）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 Hz (%2 s)</source>
        <translation>%1 Hz（%2 s）</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+34"/>
        <source>%1 (%2)</source>
        <translation>%1（%2）</translation>
    </message>
    <message>
        <location line="-30"/>
        <source>matrix %1</source>
        <translation>矩阵 %1</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>enabled</source>
        <translation>已启用</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>disabled</source>
        <translation>已禁用</translation>
    </message>
    <message>
        <location line="+45"/>
        <source>after SAVECONFIG and a reset</source>
        <translation>执行 SAVECONFIG 并复位后生效</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>at once; SAVECONFIG keeps it after a reset</source>
        <translation>立即生效；执行 SAVECONFIG 后复位仍保持</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>at once; not saved (enabled again after every start)</source>
        <translation>立即生效；不保存（每次启动后重新启用）</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>LOG COMCONFIG: %1</source>
        <translation>LOG COMCONFIG：%1</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>magnetometer aiding</source>
        <translation>磁力计辅助</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>user attitude calibration</source>
        <translation>用户姿态校准</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>IO pin mapping (PMUX)</source>
        <translation>IO 引脚映射（PMUX）</translation>
    </message>
</context>
<context>
    <name>SimulatedCanFrameLink</name>
    <message>
        <location filename="../core/sim/simulated_can_frame_link.cpp" line="+18"/>
        <source>the simulated CAN bus is not connected</source>
        <translation>模拟 CAN 总线未连接</translation>
    </message>
</context>
<context>
    <name>SphereCoverage</name>
    <message>
        <location filename="../core/calib/sphere_coverage.cpp" line="+139"/>
        <source>Turn the module slowly about each of its axes: no direction is covered yet</source>
        <translation>请绕模块的各轴缓慢转动：尚未覆盖任何方向</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Turn the module so that its %1%2 axis points along the magnetic field (towards north and, in the northern hemisphere, down)</source>
        <translation>转动模块，使其 %1%2 轴指向磁场方向（朝北；在北半球还要朝下）</translation>
    </message>
</context>
<context>
    <name>StreamDecoder</name>
    <message>
        <location filename="../core/decode/stream_decoder.cpp" line="+56"/>
        <source>The capture is of a %1 link: its registers were polled, and ImuDesk does not decode Modbus captures offline yet.</source>
        <translation>该采集文件来自 %1 链路：其寄存器是轮询读取的，ImuDesk 暂不支持离线解码 Modbus 采集文件。</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The capture is of a &quot;%1&quot; link, which this version of ImuDesk cannot decode (it decodes: %2). Open it with the version that recorded it.</source>
        <translation>该采集文件来自“%1”链路，此版本的 ImuDesk 无法解码（可解码：%2）。请用录制它的版本打开。</translation>
    </message>
</context>
<context>
    <name>UpdateFlow</name>
    <message>
        <location filename="../core/firmware/update_flow.cpp" line="+44"/>
        <location line="+213"/>
        <location line="+177"/>
        <source>unknown</source>
        <translation>未知</translation>
    </message>
    <message>
        <location line="-382"/>
        <source>idle</source>
        <translation>空闲</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>checking the image</source>
        <translation>正在检查镜像</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>identifying the module</source>
        <translation>正在识别模块</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>entering the bootloader</source>
        <translation>正在进入引导程序</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>contacting the bootloader</source>
        <translation>正在联系引导程序</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>reading the bootloader&apos;s properties</source>
        <translation>正在读取引导程序属性</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>erasing</source>
        <translation>正在擦除</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>writing</source>
        <translation>正在写入</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>verifying</source>
        <translation>正在校验</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>restarting the module</source>
        <translation>正在重启模块</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>confirming the new version</source>
        <translation>正在确认新版本</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>done</source>
        <translation>完成</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>failed</source>
        <translation>失败</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cancelled</source>
        <translation>已取消</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>the image is empty</source>
        <translation>镜像为空</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the image starts at %1, which is not a multiple of 4; the bootloader writes whole words</source>
        <translation>镜像起始地址 %1 不是 4 的倍数；引导程序按整字写入</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the image starts at %1, below the application area at %2 (that is the bootloader); this is not an application image for this module</source>
        <translation>镜像起始地址 %1 低于应用程序区起始地址 %2（该区域为引导程序）；这不是本模块的应用程序镜像</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the image ends at %1, beyond the end of the flash at %2; it does not fit this module</source>
        <translation>镜像结束地址 %1 超出闪存末尾 %2；不适用于本模块</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>the image (%1..%2) is outside the module&apos;s flash (%3..%4, %5 bytes reported by the bootloader)</source>
        <translation>镜像（%1..%2）超出模块闪存范围（%3..%4，引导程序报告 %5 字节）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the image has %1 bytes, the module&apos;s flash only %2</source>
        <translation>镜像有 %1 字节，而模块闪存只有 %2 字节</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the image starts at %1, which is not on a flash sector boundary (sectors of %2 bytes); the erase would destroy the bytes before it</source>
        <translation>镜像起始地址 %1 不在闪存扇区边界上（扇区大小 %2 字节）；擦除会破坏其之前的字节</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the image starts at %1, below the application area at %2</source>
        <translation>镜像起始地址 %1 低于应用程序区起始地址 %2</translation>
    </message>
    <message>
        <location line="+101"/>
        <source>reading the maximum packet size failed: %1</source>
        <translation>读取最大数据包大小失败：%1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>reading the flash size failed: %1</source>
        <translation>读取闪存大小失败：%1</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>the bootloader reports a maximum packet size of %1 bytes; it cannot take data</source>
        <translation>引导程序报告的最大数据包大小为 %1 字节；无法接收数据</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the bootloader reports no flash</source>
        <translation>引导程序报告没有闪存</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>bootloader: max packet %1 bytes, flash %2 bytes from %3, sectors of %4 bytes, bootloader version %5, KBOOT %6%7.%8.%9</source>
        <translation>引导程序：最大数据包 %1 字节，闪存 %2 字节（起始于 %3），扇区 %4 字节，引导程序版本 %5，KBOOT %6%7.%8.%9</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>refused before contacting the module: %1</source>
        <translation>在联系模块之前已拒绝：%1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>image: %1 bytes at %2, CRC-32 %3</source>
        <translation>镜像：%1 字节，位于 %2，CRC-32 %3</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>module %1, firmware %2, bootloader %3</source>
        <translation>模块 %1，固件 %2，引导程序 %3</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the module is already in its bootloader (an earlier update was interrupted); run the update again and allow finishing it</source>
        <translation>模块已处于引导程序中（之前的更新被中断）；请重新执行更新，并让其完成</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the module is already in its bootloader: an earlier update was interrupted; finishing it</source>
        <translation>模块已处于引导程序中：之前的更新被中断；正在完成该更新</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>nothing answered at %1 baud: neither the application (LOG VERSION) nor the bootloader (ping). Check the port, the baud rate and the power</source>
        <translation>波特率 %1 下无任何应答：应用程序（LOG VERSION）和引导程序（探测）均无应答。请检查串口、波特率和电源</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>cancelled; the module was not changed</source>
        <translation>已取消；模块未被修改</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>the module did not enter its bootloader: %1</source>
        <translation>模块未进入引导程序：%1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>bootloader answers: protocol %1%2.%3.%4</source>
        <translation>引导程序已应答：协议 %1%2.%3.%4</translation>
    </message>
    <message>
        <location line="+13"/>
        <location line="+16"/>
        <source>could not restart the module: %1</source>
        <translation>无法重启模块：%1</translation>
    </message>
    <message>
        <location line="-15"/>
        <source>refused before erasing: %1</source>
        <translation>在擦除前已拒绝：%1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>cancelled before erasing; the module was not changed</source>
        <translation>已在擦除前取消；模块未被修改</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>erasing %1 bytes at %2</source>
        <translation>正在擦除 %2 处的 %1 字节</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>refused before erasing: %1; the module was not changed</source>
        <translation>在擦除前已拒绝：%1；模块未被修改</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>erasing failed: %1. The module stays in its bootloader; run the update again</source>
        <translation>擦除失败：%1。模块停留在引导程序中；请重新执行更新</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>cancelled while writing (%1). The module stays in its bootloader without a valid application; run the update again to finish it</source>
        <translation>写入时已取消（%1）。模块停留在引导程序中，没有有效的应用程序；请重新执行更新以完成</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>writing failed: %1. The module stays in its bootloader; run the update again</source>
        <translation>写入失败：%1。模块停留在引导程序中；请重新执行更新</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 bytes written in %2 s (%3 bytes/s, %4 NAK, %5 packets resent)</source>
        <translation>%2 s 内写入 %1 字节（%3 字节/秒，%4 次 NAK，重发 %5 个数据包）</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>cancelled while verifying; the module stays in its bootloader; run the update again</source>
        <translation>校验时已取消；模块停留在引导程序中；请重新执行更新</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the image was written but cannot be verified: the bootloader does not offer ReadMemory (%1). The module was not restarted</source>
        <translation>镜像已写入但无法校验：引导程序不提供 ReadMemory 指令（%1）。模块未重启</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>verifying failed: %1. Run the update again</source>
        <translation>校验失败：%1。请重新执行更新</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>verification failed at %1: wrote %2, read %3. Run the update again</source>
        <translation>在 %1 处校验失败：写入 %2，读回 %3。请重新执行更新</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>verified: %1 bytes read back and compared</source>
        <translation>校验通过：已回读并比对 %1 字节</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the image is written and verified, but the restart failed: %1. Power-cycle the module</source>
        <translation>镜像已写入并校验通过，但重启失败：%1。请将模块断电重启</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>the image is written and verified, but the application did not answer LOG VERSION within %1 s after the restart; the image may not be a firmware for this module</source>
        <translation>镜像已写入并校验通过，但重启后 %1 s 内应用程序未应答 LOG VERSION；该镜像可能不是本模块的固件</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the image is written and verified, but the application did not answer LOG VERSION at %1 baud within %2 s after the restart, nor at any other rate; the image may not be a firmware for this module</source>
        <translation>镜像已写入并校验，但重启后应用程序在 %2 秒内未在 %1 波特率下应答 LOG VERSION，在其他波特率下也没有；该镜像可能不是本模块的固件</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>updated: firmware %1 → %2, %3 bytes verified by read-back</source>
        <translation>已更新：固件 %1 → %2，已通过回读校验 %3 字节</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>. The module restarted at %1 baud, the rate saved in it: the update ran at %2 baud, a rate that was set but not saved. It is connected again at %1 baud</source>
        <translation>。模块以其保存的波特率 %1 重新启动：更新是在 %2 波特率下进行的，该波特率已设置但未保存。现已重新以 %1 波特率连接</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>no answer at %1 baud: looking for the application at %2 baud</source>
        <translation>%1 波特率下无应答：改在 %2 波特率下查找应用程序</translation>
    </message>
</context>
<context>
    <name>VendorCsvImporter</name>
    <message>
        <location filename="../core/decode/hipnuc_vendor_csv_reader.cpp" line="+95"/>
        <source>Cannot open %1: %2</source>
        <translation>无法打开 %1：%2</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>line %1 is longer than %2 characters</source>
        <translation>第 %1 行超过 %2 个字符</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>line %1 is not the vendor&apos;s HI91 CSV header (it starts with &quot;%2&quot;)</source>
        <translation>第 %1 行不是厂商的 HI91 CSV 表头（其开头为“%2”）</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>the header has no %1 column</source>
        <translation>表头中没有 %1 列</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>line %1: the first column is &quot;%2&quot;, not HI91</source>
        <translation>第 %1 行：第一列为“%2”，而不是 HI91</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>line %1 has %2 columns, the header %3</source>
        <translation>第 %1 行有 %2 列，而表头有 %3 列</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>line %1: %2 is not a number</source>
        <translation>第 %1 行：%2 不是数字</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>line %1: pc_counter %2 is not a time in ms</source>
        <translation>第 %1 行：pc_counter %2 不是以 ms 为单位的时间</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>the file is empty: no HI91 CSV header</source>
        <translation>文件为空：没有 HI91 CSV 表头</translation>
    </message>
</context>
<context>
    <name>capture::McapRecording</name>
    <message>
        <location filename="../core/record/mcap_recorder.cpp" line="+113"/>
        <source>Recording to %1 stopped: %2. Check the free disk space.</source>
        <translation>录制到 %1 已停止：%2。请检查剩余磁盘空间。</translation>
    </message>
</context>
<context>
    <name>imudesk::bridge::LiveBridge</name>
    <message>
        <location filename="../core/bridge/live_bridge.cpp" line="+173"/>
        <source>Cannot listen on %1 port %2: %3</source>
        <translation>无法在 %1 的端口 %2 上监听：%3</translation>
    </message>
</context>
<context>
    <name>imudesk::calib::GyroCalSession</name>
    <message>
        <location filename="../core/calib/gyro_cal_session.cpp" line="+24"/>
        <source>The angle must be %1..%2 deg (2 to 5 turns); %3 is not.</source>
        <translation>角度必须为 %1..%2 deg（2 到 5 圈）；%3 不符合要求。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>A gyro calibration is already running.</source>
        <translation>陀螺仪校准已在进行中。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Starting the gyro calibration (%1 deg).</source>
        <translation>正在启动陀螺仪校准（%1 deg）。</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Stopping the gyro calibration.</source>
        <translation>正在停止陀螺仪校准。</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>Turn the module %1 deg at an even 20-100 deg/s, then stop on the mark.</source>
        <translation>以 20-100 deg/s 的匀速将模块转动 %1 deg，然后停在标记处。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The device did not answer CONFIG USRCAL START: check the link.</source>
        <translation>设备未应答 CONFIG USRCAL START：请检查链路。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The device refused CONFIG USRCAL START %1 (%2).</source>
        <translation>设备拒绝了 CONFIG USRCAL START %1（%2）。</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The device accepted the calibration (OK).</source>
        <translation>设备已接受校准结果（OK）。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The device did not answer CONFIG USRCAL STOP: check the link, then repeat.</source>
        <translation>设备未应答 CONFIG USRCAL STOP：请检查链路后重做。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The device rejected the run (ERR): the angle turned was not within 5 deg of %1 deg, or the rate was outside 20-100 deg/s or uneven. Repeat it.</source>
        <translation>设备拒绝了本次校准（ERR）：转过的角度与 %1 deg 相差超过 5 deg，或角速度超出 20-100 deg/s 或不均匀。请重做。</translation>
    </message>
</context>
<context>
    <name>imudesk::device::CanFamily</name>
    <message>
        <location filename="../core/device/can_family.cpp" line="+62"/>
        <source>connected to %1</source>
        <translation>已连接到 %1</translation>
    </message>
    <message>
        <location line="+10"/>
        <location line="+4"/>
        <source>the session was closed</source>
        <translation>会话已关闭</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>could not send frame %1: the CAN interface is not connected</source>
        <translation>无法发送帧 %1：CAN 接口未连接</translation>
    </message>
    <message>
        <location line="+67"/>
        <source>boot-up</source>
        <translation>启动报文</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>heartbeat</source>
        <translation>心跳</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>data</source>
        <translation>数据</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>SDO scan</source>
        <translation>SDO 扫描</translation>
    </message>
    <message>
        <location line="+41"/>
        <source>too many requests are waiting; try again when they are done</source>
        <translation>等待中的请求过多；请在其完成后重试</translation>
    </message>
    <message>
        <location line="+65"/>
        <source>no node answered &quot;%1&quot; to every node (address 255) within %2 ms: check the bit rate and the wiring</source>
        <translation>%2 ms 内没有节点应答发往所有节点（地址 255）的“%1”：请检查波特率和接线</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>node %1 sent no data before &quot;%2&quot; either, so its effect cannot be seen: check the node ID</source>
        <translation>节点 %1 在“%2”之前也没有发送数据，因此看不到其效果：请检查节点 ID</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>node %1 sent no data within %2 ms of &quot;%3&quot;: if its TPDOs wait for SYNC, send one; otherwise check the node ID, its output intervals and that the module is powered</source>
        <translation>节点 %1 在“%3”后 %2 ms 内没有发送数据：如果其 TPDO 等待 SYNC，请发送一个；否则请检查节点 ID、输出间隔以及模块是否上电</translation>
    </message>
    <message>
        <location line="+94"/>
        <source>node %1 still sends data after &quot;%2&quot;: check the node ID</source>
        <translation>节点 %1 在“%2”之后仍在发送数据：请检查节点 ID</translation>
    </message>
    <message>
        <location line="-101"/>
        <source>no answer within %1 ms: node %2 sent no PGN %3 after &quot;%4&quot; (a PGN its firmware or configuration does not send, or output off)</source>
        <translation>%1 ms 内没有应答：节点 %2 在“%4”之后没有发送 PGN %3（固件或配置不发送该 PGN，或输出已关闭）</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>no answer from node %1 to &quot;%2&quot; within %3 ms: check the node ID, the bit rate and the wiring</source>
        <translation>节点 %1 在 %3 ms 内未应答“%2”：请检查节点 ID、波特率和接线</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>could not send &quot;%1&quot;: the CAN interface is not connected</source>
        <translation>无法发送“%1”：CAN 接口未连接</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>the device refused &quot;%1&quot; (status %2)</source>
        <translation>设备拒绝了“%1”（状态 %2）</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>the device aborted &quot;%1&quot;: %2</source>
        <translation>设备中止了“%1”：%2</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>the device refused &quot;%1&quot;: %2</source>
        <translation>设备拒绝了“%1”：%2</translation>
    </message>
    <message>
        <location line="+58"/>
        <source>&quot;%1&quot; read back %2, expected %3</source>
        <translation>“%1”回读值为 %2，应为 %3</translation>
    </message>
    <message>
        <location line="-15"/>
        <location line="+31"/>
        <source>%1: done</source>
        <translation>%1：完成</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1 failed: %2</source>
        <translation>%1 失败：%2</translation>
    </message>
</context>
<context>
    <name>imudesk::device::CanSession</name>
    <message>
        <location filename="../core/device/can_session.cpp" line="+93"/>
        <source>HiPNUC J1939</source>
        <translation>HiPNUC J1939</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>HiPNUC CANopen</source>
        <translation>HiPNUC CANopen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>HEC495 CAN</source>
        <translation>HEC495 CAN</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>CAN</source>
        <translation>CAN</translation>
    </message>
    <message>
        <location line="+117"/>
        <location line="+7"/>
        <source>register access needs a J1939 device</source>
        <translation>寄存器访问需要 J1939 设备</translation>
    </message>
    <message>
        <location line="-6"/>
        <source>read register 0x%1</source>
        <translation>读取寄存器 0x%1</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>read register</source>
        <translation>读取寄存器</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>write register 0x%1</source>
        <translation>写入寄存器 0x%1</translation>
    </message>
    <message>
        <location line="-3"/>
        <source>write register</source>
        <translation>写入寄存器</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>SDO read</source>
        <translation>SDO 读取</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>SDO write</source>
        <translation>SDO 写入</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>read %1</source>
        <translation>读取 %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+20"/>
        <source>%1 cannot be read: %2</source>
        <translation>%1 无法读取：%2</translation>
    </message>
    <message>
        <location line="-16"/>
        <location line="+28"/>
        <source>%1 is a J1939 register: the device speaks another protocol</source>
        <translation>%1 是 J1939 寄存器：设备使用的是其他协议</translation>
    </message>
    <message>
        <location line="-18"/>
        <location line="+29"/>
        <source>%1 is a CANopen object: the device speaks another protocol</source>
        <translation>%1 是 CANopen 对象：设备使用的是其他协议</translation>
    </message>
    <message>
        <location line="-16"/>
        <source>%1 is read only</source>
        <translation>%1 为只读</translation>
    </message>
    <message>
        <location line="+9"/>
        <location line="+8"/>
        <source>read back %1</source>
        <translation>读回 %1</translation>
    </message>
    <message>
        <location line="-6"/>
        <location line="+8"/>
        <source>%1 = %2, verified by reading it back</source>
        <translation>%1 = %2，已读回校验</translation>
    </message>
    <message>
        <location line="-11"/>
        <location line="+4"/>
        <location line="+8"/>
        <location line="+11"/>
        <source>write %1</source>
        <translation>写入 %1</translation>
    </message>
    <message>
        <location line="-4"/>
        <source>%1 is an HEC495 object: the device speaks another protocol</source>
        <translation>%1 是 HEC495 对象：设备使用的是其他协议</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: the HEC495 takes one byte</source>
        <translation>%1：HEC495 只接受一个字节</translation>
    </message>
    <message>
        <location line="-22"/>
        <location line="+23"/>
        <source>%1 = %2, confirmed by the module&apos;s reply (it cannot be read back)</source>
        <translation>%1 = %2，已由模块应答确认（无法读回）</translation>
    </message>
    <message>
        <location line="-125"/>
        <source>read the firmware version</source>
        <translation>读取固件版本</translation>
    </message>
    <message>
        <location line="+17"/>
        <source> (object 0x%1, firmware %2.%3.%4)</source>
        <translation>（对象 0x%1，固件 %2.%3.%4）</translation>
    </message>
    <message>
        <location line="+5"/>
        <source> (object 0x%1: the module reports no firmware version)</source>
        <translation>（对象 0x%1：模块未报告固件版本）</translation>
    </message>
    <message>
        <location line="+106"/>
        <source>%1 cannot be written</source>
        <translation>%1 无法写入</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>0x%1 is not a data PGN</source>
        <translation>0x%1 不是数据 PGN</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the interval must be %1 to %2 ms</source>
        <translation>间隔必须为 %1 到 %2 ms</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>read back the interval</source>
        <translation>回读发送间隔</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>PGN %1 interval %2 ms</source>
        <translation>PGN %1 发送间隔 %2 ms</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>set the interval</source>
        <translation>设置发送间隔</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>TPDO channel 0..5 and a period of 0..65535 ms, please</source>
        <translation>请使用 TPDO 通道 0..5 和 0..65535 ms 的周期</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>read back the TPDO period</source>
        <translation>回读 TPDO 周期</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>TPDO%1 period %2 ms</source>
        <translation>TPDO%1 周期 %2 ms</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>set the TPDO period</source>
        <translation>设置 TPDO 周期</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the HEC495 has one PDO rate: use setHec495Rate</source>
        <translation>HEC495 只有一个 PDO 频率：请使用 setHec495Rate</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+70"/>
        <location line="+30"/>
        <location line="+123"/>
        <source>the protocol is not known yet: choose it or wait for traffic</source>
        <translation>协议尚未确定：请选择协议，或等待总线上出现数据</translation>
    </message>
    <message>
        <location line="-217"/>
        <source>the HEC495 rate code is 0 (off) to 6 (100 Hz)</source>
        <translation>HEC495 频率代码为 0（关闭）至 6（100 Hz）</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>SYNC mode needs a CANopen device and a TPDO channel 0..5</source>
        <translation>SYNC 模式需要 CANopen 设备和 TPDO 通道 0..5</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>read back the transmission type</source>
        <translation>回读传输类型</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>TPDO%1 %2</source>
        <translation>TPDO%1 %2</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>SYNC mode</source>
        <translation>SYNC 模式</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>asynchronous mode</source>
        <translation>异步模式</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>set the transmission type</source>
        <translation>设置传输类型</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>the HEC495&apos;s heartbeat is 100 ms x (N + 1): %1 to %2 ms (it cannot be turned off)</source>
        <translation>HEC495 的心跳周期为 100 ms ×（N + 1）：%1 至 %2 ms（不能关闭）</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the heartbeat needs a CANopen or HEC495 device and 0..65535 ms</source>
        <translation>心跳需要 CANopen 或 HEC495 设备，周期为 0..65535 ms</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>read back the heartbeat period</source>
        <translation>回读心跳周期</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>heartbeat %1 ms</source>
        <translation>心跳 %1 ms</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>set the heartbeat</source>
        <translation>设置心跳</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the node ID must be 1..127</source>
        <translation>节点 ID 必须为 1..127</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>traffic from node %1</source>
        <translation>节点 %1 的报文</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>node ID %1</source>
        <translation>节点 ID %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+8"/>
        <location line="+182"/>
        <source>reset</source>
        <translation>复位</translation>
    </message>
    <message>
        <location line="-189"/>
        <location line="+5"/>
        <location line="+8"/>
        <source>set the node ID</source>
        <translation>设置节点 ID</translation>
    </message>
    <message>
        <location line="-12"/>
        <location line="+5"/>
        <location line="+28"/>
        <location line="+2"/>
        <source>save</source>
        <translation>保存</translation>
    </message>
    <message>
        <location line="-24"/>
        <source>traffic from node %1 (power-cycle the HEC495 now)</source>
        <translation>节点 %1 的报文（请立即给 HEC495 重新上电）</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>HiPNUC J1939 modules support 125000, 250000, 500000, 800000 and 1000000 bit/s</source>
        <translation>HiPNUC J1939 模块支持 125000、250000、500000、800000 和 1000000 bit/s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the CANopen object 0x209A takes 125000, 250000, 500000 and 1000000 bit/s (800000 is a J1939 rate only)</source>
        <translation>CANopen 对象 0x209A 仅接受 125000、250000、500000 和 1000000 bit/s（800000 仅适用于 J1939）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>CAN bit rate %1 (saved; takes effect after a reset: reopen the session at that rate)</source>
        <translation>CAN 波特率 %1（已保存；复位后生效：请以该波特率重新打开会话）</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+2"/>
        <location line="+8"/>
        <source>set the bit rate</source>
        <translation>设置波特率</translation>
    </message>
    <message>
        <location line="-2"/>
        <source>the HEC495 supports 10000 to 500000 bit/s (see its manual&apos;s table)</source>
        <translation>HEC495 支持 10000 至 500000 bit/s（见其手册中的表格）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CAN bit rate %1 (takes effect after a power cycle: reopen the session at that rate)</source>
        <translation>CAN 波特率 %1（重新上电后生效：请以该波特率重新打开会话）</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>attitude reset mode 1, 2, 3 or 5, please</source>
        <translation>姿态复位模式须为 1、2、3 或 5</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>attitude reset %1</source>
        <translation>姿态复位 %1</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>attitude reset</source>
        <translation>姿态复位</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>CANopen zeroing: mode 2 (set zero) or 5 (clear), please</source>
        <translation>CANopen 置零：模式须为 2（设置零位）或 5（清除零位）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>zero %1</source>
        <translation>置零 %1</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>set zero</source>
        <translation>设置零位</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>attitude reset needs a HiPNUC J1939 or CANopen device</source>
        <translation>姿态复位需要 HiPNUC J1939 或 CANopen 设备</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the inclinometer axis is X (0) or Y (1)</source>
        <translation>倾角仪轴为 X（0）或 Y（1）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>inclinometer %1 %2</source>
        <translation>倾角仪 %1 %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>reversed</source>
        <translation>反向</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>default direction</source>
        <translation>默认方向</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+6"/>
        <source>read back the inclinometer sign</source>
        <translation>回读倾角仪正负方向</translation>
    </message>
    <message>
        <location line="-4"/>
        <location line="+6"/>
        <source>set the inclinometer sign</source>
        <translation>设置倾角仪正负方向</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the inclinometer sign needs a HiPNUC J1939 or CANopen device</source>
        <translation>倾角仪正负方向需要 HiPNUC J1939 或 CANopen 设备</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the PDO mode is an HEC495 setting</source>
        <translation>PDO 模式是 HEC495 的设置</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the extended variant&apos;s PDO format is 0 (X) or 1 (X and Y)</source>
        <translation>扩展帧方式的 PDO 格式为 0（X）或 1（X 和 Y）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the PDO mode is 0 (float), 1 (fixed point) or 3 (float, 0x180 and 0x280 only)</source>
        <translation>PDO 模式为 0（浮点）、1（定点）或 3（浮点，仅 0x180 和 0x280）</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>the work mode is an HEC495 setting on standard frames</source>
        <translation>工作模式是 HEC495 标准帧方式的设置</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the work mode is 0x02 (pitch, roll, acceleration, rate) or 0x0A (rate at 500 Hz)</source>
        <translation>工作模式为 0x02（俯仰、横滚、加速度、角速度）或 0x0A（以 500 Hz 输出角速度）</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>output on or off for every node needs CANopen or an HEC495 on standard frames (NMT)</source>
        <translation>对所有节点开关输出需要 CANopen 或标准帧方式的 HEC495（NMT）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>NMT start, every node</source>
        <translation>NMT 启动，所有节点</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>NMT stop, every node</source>
        <translation>NMT 停止，所有节点</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>output on</source>
        <translation>开启输出</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>output off</source>
        <translation>关闭输出</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>output enable</source>
        <translation>输出使能</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>NMT start</source>
        <translation>NMT 启动</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>NMT stop</source>
        <translation>NMT 停止</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>&quot;%1&quot; needs a HiPNUC J1939 or CANopen device (the HEC495 saves at once)</source>
        <translation>“%1”需要 HiPNUC J1939 或 CANopen 设备（HEC495 会立即保存）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>save configuration</source>
        <translation>保存配置</translation>
    </message>
    <message>
        <location line="+8"/>
        <location line="+1"/>
        <location line="+8"/>
        <source>factory defaults</source>
        <translation>恢复出厂设置</translation>
    </message>
    <message>
        <location line="-2"/>
        <source> (firmware 1.6: they take effect at the next power-up)</source>
        <translation>（固件 1.6：下次上电后生效）</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>a one-shot trigger needs a J1939 device and a data PGN</source>
        <translation>单次触发需要 J1939 设备和数据 PGN</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>trigger PGN %1</source>
        <translation>触发 PGN %1</translation>
    </message>
</context>
<context>
    <name>imudesk::device::GroupRecording</name>
    <message>
        <location filename="../core/record/group_recording.cpp" line="+47"/>
        <source>A session recording is already running.</source>
        <translation>会话录制已在进行中。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>No device to record: connect one first.</source>
        <translation>没有可录制的设备：请先连接一台设备。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 already holds a recorded session; choose another folder.</source>
        <translation>%1 中已有录制的会话；请选择其他文件夹。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Cannot create the folder %1: check that the place exists and can be written to.</source>
        <translation>无法创建文件夹 %1：请检查该位置是否存在且可写入。</translation>
    </message>
    <message>
        <location line="+57"/>
        <source>The device&apos;s tab was closed or its link replaced; its capture ends here.</source>
        <translation>该设备的标签页已关闭或其连接已被替换；其记录到此结束。</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>None of the devices could be recorded: %1.</source>
        <translation>所有设备均无法录制：%1。</translation>
    </message>
    <message>
        <location line="+49"/>
        <source>Stopped in the device&apos;s own tab (Record or Disconnect) before the session ended.</source>
        <translation>会话结束前已在该设备自己的标签页中停止（录制或断开）。</translation>
    </message>
</context>
<context>
    <name>imudesk::device::Hec495Family</name>
    <message>
        <location filename="../core/device/hec495_family.cpp" line="+66"/>
        <source>the request&apos;s data is longer than a Witlink frame can carry</source>
        <translation>请求数据超出 Witlink 帧所能承载的长度</translation>
    </message>
    <message>
        <location line="+44"/>
        <source>no HEC495 answered on %1 at %2 baud: check the wiring (RS-232 TXD/RXD or RS-485 A/B), the power, the baud rate and the module address (%3)</source>
        <translation>%1 上没有 HEC495 应答（波特率 %2）：请检查接线（RS-232 TXD/RXD 或 RS-485 A/B）、电源、波特率和模块地址（%3）</translation>
    </message>
    <message>
        <location line="-1"/>
        <source>any supported</source>
        <translation>任一支持值</translation>
    </message>
    <message>
        <location line="+80"/>
        <source>no reply to &quot;%1&quot; after %2 attempts of %3 ms (check the baud rate and the module address; an RS-485 module that streams may miss commands: set question/answer mode)</source>
        <translation>“%1”尝试 %2 次（每次 %3 ms）均无应答（请检查波特率和模块地址；处于连续输出状态的 RS-485 模块可能漏收指令：请设为问答模式）</translation>
    </message>
    <message>
        <location line="+160"/>
        <source>the module answered with an invalid reply: %1</source>
        <translation>模块返回了无效应答：%1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the module reported failure (FF) for &quot;%1&quot;</source>
        <translation>模块对“%1”报告失败（FF）</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>the module streams: identified without a request</source>
        <translation>模块正在连续输出：无需请求即已识别</translation>
    </message>
</context>
<context>
    <name>imudesk::device::Hec495Session</name>
    <message>
        <location filename="../core/device/hec495_session.cpp" line="+77"/>
        <source>the declination must be between -99.9 and 99.9 degrees (got %1)</source>
        <translation>磁偏角必须在 -99.9 至 99.9 度之间（当前为 %1）</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>the HEC495 supports 2400, 4800, 9600, 19200 and 115200 baud (got %1)</source>
        <translation>HEC495 支持的波特率为 2400、4800、9600、19200 和 115200（当前为 %1）</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>the output rate must be 0 (question/answer), 5, 10, 15, 25, 50 or 100 Hz (got %1)</source>
        <translation>输出频率必须为 0（问答模式）、5、10、15、25、50 或 100 Hz（当前为 %1）</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the output content must be 0 to 3</source>
        <translation>输出内容必须为 0 至 3</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the address must be 0 to 255 (got %1)</source>
        <translation>地址必须为 0 至 255（当前为 %1）</translation>
    </message>
</context>
<context>
    <name>imudesk::device::HipnucSerialFamily</name>
    <message>
        <location filename="../core/device/hipnuc_family.cpp" line="+202"/>
        <source>The device that came back on %1 is a different one (serial %2, before %3). Its data continues in this session.</source>
        <translation>%1 上重新出现的是另一台设备（序列号 %2，之前为 %3）。其数据将继续记录在本会话中。</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>no reply within %1 ms (the device ignores commands it does not know)</source>
        <translation>%1 ms 内无应答（设备不响应它不认识的指令）</translation>
    </message>
    <message>
        <location filename="../core/device/hipnuc_family_baud.cpp" line="+66"/>
        <source>No HiPNUC device answered on %1 at any baud rate (115200, 921600, 460800, 230400, 256000, 57600, 38400, 19200, 9600, 4800). Check the cable and the power, and that no other program uses the port.</source>
        <translation>%1 上在所有波特率（115200、921600、460800、230400、256000、57600、38400、19200、9600、4800）下都没有 HiPNUC 设备应答。请检查线缆和电源，并确认没有其他程序占用该串口。</translation>
    </message>
    <message>
        <location line="-20"/>
        <source>trying %1 baud</source>
        <translation>正在尝试 %1 波特率</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1 at %2 baud</source>
        <translation>%1，波特率 %2</translation>
    </message>
    <message>
        <location line="+43"/>
        <location line="+50"/>
        <source>the port is not open</source>
        <translation>串口未打开</translation>
    </message>
    <message>
        <location line="-32"/>
        <source>the device refused SERIALCONFIG %1 (%2) and stays at %3 baud</source>
        <translation>设备拒绝了 SERIALCONFIG %1（%2），仍保持波特率 %3</translation>
    </message>
    <message>
        <location line="+11"/>
        <location line="+36"/>
        <source>the device answers at %1 baud</source>
        <translation>设备在波特率 %1 下应答</translation>
    </message>
    <message>
        <location line="-31"/>
        <source>the device did not answer at %1 baud; it answers at %2 baud</source>
        <translation>设备在波特率 %1 下无应答；在波特率 %2 下有应答</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the device answers neither at %1 nor at %2 baud nor at any other rate: check the cable and power-cycle it</source>
        <translation>设备在波特率 %1、%2 及其他任何波特率下均无应答：请检查线缆并给设备重新上电</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>the device does not answer at any baud rate</source>
        <translation>设备在任何波特率下均无应答</translation>
    </message>
</context>
<context>
    <name>imudesk::device::LinkOpener</name>
    <message>
        <location filename="../core/links/link_opener.cpp" line="+118"/>
        <source>%1: no serial device family is called &quot;%2&quot;</source>
        <translation>%1：没有名为“%2”的串口设备系列</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>The simulated Modbus device could not start: %1</source>
        <translation>模拟 Modbus 设备无法启动：%1</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>The simulated CAN device could not start on %1:%2: %3</source>
        <translation>模拟 CAN 设备无法在 %1:%2 上启动：%3</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>A capture file cannot be simulated.</source>
        <translation>采集文件无法模拟。</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1: the device&apos;s family is found by a detection, which does not finish at once</source>
        <translation>%1：设备系列需要检测才能确定，检测不会立即完成</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>%1 cannot be read. Check that the file exists and that you may read it.</source>
        <translation>无法读取 %1。请检查文件是否存在，以及您是否有读取权限。</translation>
    </message>
    <message>
        <location line="+78"/>
        <source>the port of %1 was lost while it was handed to the device&apos;s session</source>
        <translation>%1 的端口在交给设备会话时丢失</translation>
    </message>
</context>
<context>
    <name>imudesk::device::ModbusSession</name>
    <message>
        <location filename="../core/device/modbus_session.cpp" line="+95"/>
        <source>ILLEGAL FUNCTION (01): the device does not support this request at %1.</source>
        <translation>ILLEGAL FUNCTION（01，非法功能）：设备不支持对 %1 的此请求。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>ILLEGAL DATA ADDRESS (02): %1 does not exist on this device or cannot be accessed this way (write-only or read-only). Check the register map of the device&apos;s manual.</source>
        <translation>ILLEGAL DATA ADDRESS（02，非法数据地址）：此设备上不存在 %1，或不能以此方式访问（只写或只读）。请查阅设备手册中的寄存器表。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>ILLEGAL DATA VALUE (03): the device refused the value or count for %1. Check the register&apos;s range.</source>
        <translation>ILLEGAL DATA VALUE（03，非法数据值）：设备拒绝了 %1 的数值或数量。请检查该寄存器的取值范围。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>SERVER DEVICE FAILURE (04): the device failed while handling %1. Reset it and try again.</source>
        <translation>SERVER DEVICE FAILURE（04，从站设备故障）：设备处理 %1 时出错。请复位设备后重试。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>SERVER DEVICE BUSY (06): the device is busy; try %1 again later.</source>
        <translation>SERVER DEVICE BUSY（06，从站设备忙）：设备正忙；请稍后重试 %1。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Modbus exception %1 at %2.</source>
        <translation>%2 处出现 Modbus 异常 %1。</translation>
    </message>
    <message>
        <location filename="../core/device/modbus_family.cpp" line="+119"/>
        <source>Port open at %1 baud</source>
        <translation>串口已打开，波特率 %1</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>The serial port %1 cannot run at %2 baud. Connect again at the device&apos;s new rate.</source>
        <translation>串口 %1 无法以 %2 波特率运行。请以设备的新波特率重新连接。</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>a Modbus node ID is 0 to 247 (got %1)</source>
        <translation>Modbus 节点 ID 应为 0 到 247（收到 %1）</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>register 0x%1</source>
        <translation>寄存器 0x%1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>No reply from node %1 at %2 baud within %3 ms. Check the node ID, the baud rate and parity, and the RS-485 wiring (A/B).</source>
        <translation>节点 %1 在 %3 ms 内无应答（波特率 %2）。请检查节点 ID、波特率和校验位，以及 RS-485 接线（A/B）。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The request to node %1 failed: %2</source>
        <translation>对节点 %1 的请求失败：%2</translation>
    </message>
    <message>
        <location line="+93"/>
        <source>the reply carries another number of registers than asked for</source>
        <translation>应答中的寄存器数量与请求的不一致</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Reading the identity of node %1</source>
        <translation>正在读取节点 %1 的设备标识</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>Modbus node %1</source>
        <translation>Modbus 节点 %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Node %1 at %2 baud</source>
        <translation>节点 %1，波特率 %2</translation>
    </message>
    <message>
        <location line="+58"/>
        <source>Node %1 answers again</source>
        <translation>节点 %1 已恢复应答</translation>
    </message>
    <message>
        <location line="+42"/>
        <source>not connected</source>
        <translation>未连接</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a read takes 1 to 125 registers</source>
        <translation>每次读取 1 至 125 个寄存器</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Not connected: connect first.</source>
        <translation>未连接：请先连接。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 is not a valid value for %2 (%3).</source>
        <translation>%1 不是 %2 的有效值（%3）。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Register address and value must be 0..65535.</source>
        <translation>寄存器地址和数值必须为 0..65535。</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>Done: %1.</source>
        <translation>完成：%1。</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Written, but reading it back failed: %1</source>
        <translation>已写入，但回读失败：%1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Written, but the device reads back %1 instead of %2.</source>
        <translation>已写入，但设备回读值为 %1，而不是 %2。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Read back: %1.</source>
        <translation>回读值：%1。</translation>
    </message>
    <message>
        <location line="+99"/>
        <source>The serial port %1 cannot run at %2 baud.</source>
        <translation>串口 %1 无法以 %2 波特率运行。</translation>
    </message>
    <message>
        <location line="+43"/>
        <source>HEC495 compass (pitch %1 deg)</source>
        <translation>HEC495 罗盘（俯仰角 %1 deg）</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>answers, identity unreadable</source>
        <translation>有应答，无法读取设备标识</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>The serial port %1 cannot return to %2 baud.</source>
        <translation>串口 %1 无法恢复到 %2 波特率。</translation>
    </message>
    <message>
        <location line="-43"/>
        <source>answers with Modbus exception %1</source>
        <translation>应答 Modbus 异常 %1</translation>
    </message>
</context>
<context>
    <name>imudesk::device::SerialFamilyScan</name>
    <message>
        <location filename="../core/links/serial_family_scan.cpp" line="+52"/>
        <source>trying %1 baud</source>
        <translation>正在尝试 %1 波特</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>no device answered on %1 at %2 baud (looked for %3): check the power, the wiring and that no other program holds the port</source>
        <translation>%1 在 %2 波特率下没有设备应答（查找的是 %3）：请检查电源、接线，以及端口是否被其他程序占用</translation>
    </message>
    <message>
        <location line="+2"/>
        <source> or </source>
        <translation> 或 </translation>
    </message>
    <message>
        <location filename="../core/links/serial_family_scan.h" line="+37"/>
        <source>serial</source>
        <translation>串口</translation>
    </message>
</context>
<context>
    <name>imudesk::device::SessionEngine</name>
    <message>
        <location filename="../core/device/session_engine.cpp" line="+133"/>
        <source>the link went to the device&apos;s own session</source>
        <translation>链路已交给设备自己的会话</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>the connection was closed</source>
        <translation>连接已关闭</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>disconnected — waiting for the device to come back</source>
        <translation>已断开，正在等待设备重新连接</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>automatic reconnection was turned off</source>
        <translation>自动重连已关闭</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1 at %2 baud (reconnected)</source>
        <translation>%1，波特率 %2（已重连）</translation>
    </message>
    <message>
        <location line="+56"/>
        <source>the port is not open</source>
        <translation>串口未打开</translation>
    </message>
    <message>
        <location line="+55"/>
        <source>writing to the port failed</source>
        <translation>向串口写入失败</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>no reply within %1 ms</source>
        <translation>%1 ms 内没有应答</translation>
    </message>
    <message>
        <location line="+75"/>
        <source>Bytes keep arriving on %1 but none of them form a frame: the device probably runs at another baud rate now. Disconnect and connect again with the baud rate set to Auto.</source>
        <translation>%1 上持续收到字节，但无法组成任何数据帧：设备可能已改用其他波特率。请断开连接，并将波特率设为“自动”后重新连接。</translation>
    </message>
</context>
<context>
    <name>imudesk::discovery::BenchSweep</name>
    <message>
        <location filename="../core/discovery/bench_sweep.cpp" line="+120"/>
        <source>looking for a serial device</source>
        <translation>正在查找串口设备</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>no serial device answered; as a Modbus line %1 of %2 addresses and rates were asked before the time was up (nothing answered): give the sweep more time</source>
        <translation>没有串口设备应答；作为 Modbus 线路，在时间用完前已询问 %2 个地址与波特率组合中的 %1 个（均无应答）：请给扫描更多时间</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the sweep was cancelled while the port was asked as a Modbus line</source>
        <translation>该端口作为 Modbus 线路询问期间扫描被取消</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the time was up before anything answered</source>
        <translation>在有设备应答之前时间已用完</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+257"/>
        <source>the sweep was cancelled</source>
        <translation>扫描已取消</translation>
    </message>
    <message>
        <location line="-238"/>
        <source>%1 at %2 baud: reading its identity</source>
        <translation>%1，波特率 %2：正在读取其身份信息</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>the sweep ended before it said who it is</source>
        <translation>扫描在其报告身份之前已结束</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>it streams, but did not say who it is within %1 s</source>
        <translation>设备在输出数据，但 %1 s 内未报告其身份</translation>
    </message>
    <message>
        <location line="+59"/>
        <source>asking it as a Modbus RTU line</source>
        <translation>正在作为 Modbus RTU 线路询问</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>known by its answer at the angle registers (no identity block)</source>
        <translation>根据其角度寄存器的应答识别（无身份信息块）</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1 replies to id %2 failed their CRC while other ids&apos; replies were whole: two devices answering at once garble each other</source>
        <translation>发往 ID %2 的应答中有 %1 个 CRC 校验失败，而其他 ID 的应答完好：两台设备同时应答，相互干扰</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Connect the devices one at a time and give each its own Modbus id (Settings, MD_ID; save and reset), then sweep again.</source>
        <translation>逐台连接设备，并为每台设置各自的 Modbus ID（设置中的 MD_ID，保存并复位），然后重新扫描。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Modbus id %1 answers at %2 baud</source>
        <translation>Modbus ID %1 在波特率 %2 下应答</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>%1 bytes arrived but none formed a frame of any family at any rate%2: check the wiring (A/B swapped on RS-485, TX/RX), the parity and that the device is one ImuDesk knows</source>
        <translation>收到 %1 字节，但在任何波特率下都不构成任何设备系列的帧%2：请检查接线（RS-485 的 A/B 是否接反、TX/RX）、校验位，以及该设备是否为 ImuDesk 支持的设备</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>, nor a Modbus reply</source>
        <translation>，也不是 Modbus 应答</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>nothing answered at any rate%1: check the power and the wiring, or that a device is connected at all</source>
        <translation>在任何波特率下均无应答%1：请检查电源和接线，或确认是否连接了设备</translation>
    </message>
    <message>
        <location line="+2"/>
        <source> (serial families and Modbus ids 1-247)</source>
        <translation>（串口设备系列及 Modbus ID 1-247）</translation>
    </message>
    <message>
        <location line="+62"/>
        <source>the time was up before the bus was heard at every bit rate</source>
        <translation>尚未在所有波特率下监听总线，时间已用完</translation>
    </message>
    <message>
        <location line="+49"/>
        <source>%1 bit/s</source>
        <translation>%1 bit/s</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>the interface&apos;s rate</source>
        <translation>接口当前的波特率</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>errors at every bit rate tried (%1): check the termination (120 Ω at each end), CAN-H/CAN-L and the ground; nothing was sent on this bus</source>
        <translation>尝试的每个波特率（%1）下都有错误：请检查终端电阻（两端各 120 Ω）、CAN-H/CAN-L 和地线；未向该总线发送任何报文</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>listening at %1</source>
        <translation>正在以 %1 监听</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>asking the nodes at %1</source>
        <translation>正在以 %1 询问各节点</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>Qt&apos;s virtualcan interface has no bit rate</source>
        <translation>Qt 的 virtualcan 接口没有波特率</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1 frames at %2, none of a device ImuDesk knows, and nothing answered</source>
        <translation>以 %2 收到 %1 帧，均不属于 ImuDesk 支持的设备，且无应答</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>no traffic at any bit rate (%1) and nothing answered when asked at %2: check the power and the wiring</source>
        <translation>在任何波特率（%1）下均无报文，以 %2 询问时也无应答：请检查电源和接线</translation>
    </message>
</context>
<context>
    <name>imudesk::discovery::SimulatedBench</name>
    <message>
        <location filename="../core/discovery/simulated_bench.cpp" line="+25"/>
        <source>%1 could not start: %2</source>
        <translation>%1 无法启动：%2</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>A simulated serial device</source>
        <translation>一个模拟串口设备</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The simulated Modbus module</source>
        <translation>模拟 Modbus 模块</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>A simulated CAN module</source>
        <translation>一个模拟 CAN 模块</translation>
    </message>
</context>
<context>
    <name>imudesk::io::CanTransport</name>
    <message>
        <location filename="../core/io/can_transport.cpp" line="+75"/>
        <source>the CAN plugin &quot;%1&quot; is not installed (available: %2)</source>
        <translation>未安装 CAN 插件“%1”（可用插件：%2）</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>cannot create CAN interface %1: %2</source>
        <translation>无法创建 CAN 接口 %1：%2</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>CAN interface error: %1</source>
        <translation>CAN 接口错误：%1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the CAN interface %1 closed; received data is kept</source>
        <translation>CAN 接口 %1 已关闭；已接收的数据会保留</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>cannot open CAN interface %1: %2 (check the interface name, that it is up, and your permissions)</source>
        <translation>无法打开 CAN 接口 %1：%2（请检查接口名称、接口是否已启用以及访问权限）</translation>
    </message>
    <message>
        <location line="+49"/>
        <source>frames written while the CAN interface %1 was connecting could not be sent</source>
        <translation>CAN 接口 %1 连接期间写入的帧未能发出</translation>
    </message>
</context>
<context>
    <name>imudesk::io::SerialTransport</name>
    <message>
        <location filename="../core/io/serial_transport.cpp" line="+28"/>
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
        <source>No permission to open %1. On Linux add your user to the dialout group (sudo usermod -aG dialout $USER), then log out and in again; or install the udev rule that docs/INSTALLING.md describes (60-imudesk-serial.rules).</source>
        <translation>没有打开 %1 的权限。在 Linux 上请将当前用户加入 dialout 组（sudo usermod -aG dialout $USER），然后注销并重新登录；或安装 docs/INSTALLING.md 中所述的 udev 规则（60-imudesk-serial.rules）。</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Could not open %1: %2</source>
        <translation>无法打开 %1：%2</translation>
    </message>
    <message>
        <location line="+225"/>
        <source>The connection to %1 was lost (%2). Check the cable; everything received so far is kept.</source>
        <translation>与 %1 的连接已断开（%2）。请检查线缆；已接收的数据都会保留。</translation>
    </message>
</context>
<context>
    <name>imudesk::model::MainStatus</name>
    <message>
        <location filename="../core/model/main_status.cpp" line="+10"/>
        <source>HiPNUC manual v1.7.1, 5.9.13</source>
        <translation>HiPNUC 手册 v1.7.1，5.9.13</translation>
    </message>
    <message>
        <location line="+2"/>
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
        <source>the vendor&apos;s SDK; the v1.7.1 manual (5.9.13) lists bit 9 as reserved</source>
        <translation>厂商 SDK；v1.7.1 手册（5.9.13）将第 9 位列为保留</translation>
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
        <source>HiPNUC manual v1.7.1, 5.9.13 (named UTC_SYNCED there, but 1 means not synchronised; the SDK calls it UTC_UNSYNC)</source>
        <translation>HiPNUC 手册 v1.7.1，5.9.13（手册中名为 UTC_SYNCED，但 1 表示未同步；SDK 称其为 UTC_UNSYNC）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>This frame corresponds to a SYNC_OUT pulse.</source>
        <translation>该帧对应一个 SYNC_OUT 脉冲。</translation>
    </message>
</context>
<context>
    <name>imudesk::models::CalibrationHistoryModel</name>
    <message>
        <location filename="../core/itemmodels/calibration_history_model.cpp" line="+41"/>
        <source>Magnetometer</source>
        <translation>磁力计</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Gyro scale factor</source>
        <translation>陀螺仪标度因数</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Attitude reset</source>
        <translation>姿态复位</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Compass (HEC495)</source>
        <translation>罗盘（HEC495）</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>|B| %1 µT, fit error %2 %, coverage %3 %</source>
        <translation>|B| %1 µT，拟合误差 %2 %，覆盖率 %3 %</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>scale error %1 %</source>
        <translation>标度因数误差 %1 %</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>Time</source>
        <translation>时间</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Calibration</source>
        <translation>校准</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Verdict</source>
        <translation>结论</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Result</source>
        <translation>结果</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Firmware</source>
        <translation>固件</translation>
    </message>
</context>
<context>
    <name>imudesk::models::CanFrameMonitorModel</name>
    <message>
        <location filename="../core/itemmodels/can_frame_monitor_model.cpp" line="+32"/>
        <source>Ext</source>
        <translation>扩展</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Std</source>
        <translation>标准</translation>
    </message>
    <message>
        <location line="+2"/>
        <source> FD</source>
        <translation> FD</translation>
    </message>
    <message>
        <location line="+2"/>
        <source> RTR</source>
        <translation> RTR</translation>
    </message>
    <message>
        <location line="+1"/>
        <source> Tx</source>
        <translation> 发送</translation>
    </message>
    <message>
        <location line="+0"/>
        <source> Rx</source>
        <translation> 接收</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>CAN-ID</source>
        <translation>CAN-ID</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Type</source>
        <translation>类型</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Length</source>
        <translation>长度</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Data</source>
        <translation>数据</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cycle time (ms)</source>
        <translation>周期（ms）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Count</source>
        <translation>计数</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Meaning</source>
        <translation>含义</translation>
    </message>
    <message>
        <location line="+132"/>
        <source>cannot write %1: %2</source>
        <translation>无法写入 %1：%2</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>writing %1 failed: %2 (is the disk full?)</source>
        <translation>写入 %1 失败：%2（磁盘是否已满？）</translation>
    </message>
</context>
<context>
    <name>imudesk::models::ClockStatsModel</name>
    <message>
        <location filename="../core/itemmodels/clock_stats_model.cpp" line="+39"/>
        <source>device counter</source>
        <translation>设备计数器</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>request/answer</source>
        <translation>请求/应答</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>receive stamp</source>
        <translation>接收时间戳</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>aligned</source>
        <translation>已对齐</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>uncertain: fitting, %1 s of the %2 s it needs</source>
        <translation>不确定：正在拟合，已有 %1 s，需要 %2 s</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>free-running: the interface gives no receive stamps</source>
        <translation>自由运行：接口不提供接收时间戳</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>free-running: no device time yet</source>
        <translation>自由运行：尚无设备时间</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>The device&apos;s own time, fitted against the host&apos;s clock from its least delayed samples</source>
        <translation>设备自身的时间，由延迟最小的样本对主机时钟拟合得到</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>No device time: the sample was taken between the request and its answer; the middle is used</source>
        <translation>无设备时间：采样时刻位于请求与应答之间；取两者的中点</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>No device time: the interface&apos;s receive stamp less the frame&apos;s time on the bus</source>
        <translation>无设备时间：取接口的接收时间戳减去该帧在总线上的传输时间</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>How fast the device&apos;s clock runs against the host&apos;s, in parts per million</source>
        <translation>设备时钟相对主机时钟的快慢，单位 ppm（百万分之一）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Scatter of the least delayed samples about the fitted line, in ms</source>
        <translation>延迟最小的样本相对拟合直线的离散程度，单位 ms</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Half the request-to-answer time: the sampling instant lies within this, in ms</source>
        <translation>从请求到应答时间的一半：采样时刻位于此范围内，单位 ms</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Times the device&apos;s counter restarted or its time base changed (each starts the fit again)</source>
        <translation>设备计数器重启或其时间基准改变的次数（每次都会重新开始拟合）</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>Stream</source>
        <translation>数据流</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Time from</source>
        <translation>时间来源</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>State</source>
        <translation>状态</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Drift (ppm)</source>
        <translation>漂移（ppm）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Jitter (ms)</source>
        <translation>抖动（ms）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>± (ms)</source>
        <translation>±（ms）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Resets</source>
        <translation>复位次数</translation>
    </message>
</context>
<context>
    <name>imudesk::models::CommandLogModel</name>
    <message>
        <location filename="../core/itemmodels/command_log_model.cpp" line="+88"/>
        <source>waiting</source>
        <translation>等待中</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>ERR</source>
        <translation>ERR</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>invalid</source>
        <translation>无效应答</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>timeout</source>
        <translation>超时</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cancelled</source>
        <translation>已取消</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not sent</source>
        <translation>未发送</translation>
    </message>
    <message>
        <location line="+50"/>
        <source>Time</source>
        <translation>时间</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Command</source>
        <translation>指令</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Status</source>
        <translation>状态</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Reply</source>
        <translation>应答</translation>
    </message>
</context>
<context>
    <name>imudesk::models::LatestValuesModel</name>
    <message>
        <location filename="../core/itemmodels/latest_values_model.cpp" line="+171"/>
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
        <location line="+17"/>
        <source>%1 (%2 s old)</source>
        <comment>a value that stopped arriving, with its age</comment>
        <translation>%1（%2 秒前）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 (%2 min old)</source>
        <comment>a value that stopped arriving, with its age</comment>
        <translation>%1（%2 分钟前）</translation>
    </message>
    <message>
        <location line="+101"/>
        <source>0 invalid</source>
        <translation>0 解无效</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>1 aligning</source>
        <translation>1 对准中</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>3 navigating</source>
        <translation>3 组合导航中</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>6 dead reckoning</source>
        <translation>6 惯性递推中</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>0 no fix</source>
        <translation>0 未定位</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>1 single</source>
        <translation>1 单点定位</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>2 DGNSS</source>
        <translation>2 差分定位</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>4 RTK fixed</source>
        <translation>4 RTK 固定解</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>5 RTK float</source>
        <translation>5 RTK 浮点解</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>true</source>
        <translation>真北</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>magnetic</source>
        <translation>磁北</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>none (%1)</source>
        <translation>无 (%1)</translation>
    </message>
    <message>
        <location line="+53"/>
        <source>%1 (NWU)</source>
        <comment>an attitude quantity of a module set to North-West-Up</comment>
        <translation>%1（NWU）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Device time</source>
        <translation>设备时间</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>INS status</source>
        <translation>组合导航状态</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Latitude</source>
        <translation>纬度</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Longitude</source>
        <translation>经度</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Altitude (MSL)</source>
        <translation>海拔高度</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Velocity east</source>
        <translation>东向速度</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Velocity north</source>
        <translation>北向速度</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Velocity up</source>
        <translation>天向速度</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>GNSS fix</source>
        <translation>GNSS 定位</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>UTC time</source>
        <translation>UTC 时间</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Heave</source>
        <translation>垂荡</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Surge</source>
        <translation>纵荡</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Sway</source>
        <translation>横荡</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Inclination X</source>
        <translation>X 轴倾角</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Inclination Y</source>
        <translation>Y 轴倾角</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>UTC date</source>
        <translation>UTC 日期</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Heave/surge/sway frequency</source>
        <translation>升沉/纵荡/横荡频率</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Acceleration E N U</source>
        <translation>加速度 东 北 天</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>GNSS heading fix</source>
        <translation>GNSS 航向解状态</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Odometer speed</source>
        <translation>里程计速度</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Geoid undulation</source>
        <translation>高程异常</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Differential age</source>
        <translation>差分龄期</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Node ID</source>
        <translation>节点 ID</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Filter updates</source>
        <translation>滤波器量测更新</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>KF accelerometer bias</source>
        <translation>KF 加速度零偏</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>KF gyroscope bias</source>
        <translation>KF 陀螺零偏</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>GNSS std position, velocity</source>
        <translation>GNSS 位置、速度标准差</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Dual antenna</source>
        <translation>双天线</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>GNSS lat lon alt</source>
        <translation>GNSS 纬度 经度 高度</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>GNSS velocity E N U</source>
        <translation>GNSS 速度 东 北 天</translation>
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
        <source>UTC</source>
        <translation>UTC</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>G</source>
        <translation>G</translation>
    </message>
    <message>
        <location line="+0"/>
        <location line="+19"/>
        <source>m/s²</source>
        <translation>m/s²</translation>
    </message>
    <message>
        <location line="-18"/>
        <source>deg/s</source>
        <translation>°/s</translation>
    </message>
    <message>
        <location line="+0"/>
        <location line="+19"/>
        <source>rad/s</source>
        <translation>rad/s</translation>
    </message>
    <message>
        <location line="-18"/>
        <source>µT</source>
        <translation>µT</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+4"/>
        <location line="+3"/>
        <location line="+1"/>
        <location line="+2"/>
        <source>deg</source>
        <translation>°</translation>
    </message>
    <message>
        <location line="-9"/>
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
        <location line="+1"/>
        <location line="+2"/>
        <location line="+14"/>
        <source>m</source>
        <translation>m</translation>
    </message>
    <message>
        <location line="-15"/>
        <location line="+14"/>
        <source>m/s</source>
        <translation>m/s</translation>
    </message>
    <message>
        <location line="-10"/>
        <source>relative</source>
        <translation>相对值</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Hz</source>
        <translation>Hz</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>s</source>
        <translation>s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>m, m/s</source>
        <translation>m, m/s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>m, deg, deg</source>
        <translation>m, deg, deg</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>deg, deg, m</source>
        <translation>deg, deg, m</translation>
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
        <location line="+5"/>
        <source>%1 angle, in degrees: Euler angles 3-1-2 in the North-West-Up frame the module is set to (CONFIG IMU COORD 4); the yaw is 0 with the module&apos;s Y axis pointing west.</source>
        <translation>%1角，单位为度：模块所设北西天坐标系（CONFIG IMU COORD 4）下的 3-1-2 欧拉角；模块 Y 轴指向西时航向角为 0。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Roll</source>
        <translation>横滚</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Pitch</source>
        <translation>俯仰</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Yaw</source>
        <translation>航向</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Roll angle, in degrees (Euler angles in the device&apos;s convention, ENU 312 by default).</source>
        <translation>横滚角，单位 °（设备约定的欧拉角，默认 ENU 312 顺序）。</translation>
    </message>
    <message>
        <location line="-4"/>
        <source>Pitch angle, in degrees (Euler angles in the device&apos;s convention, ENU 312 by default).</source>
        <translation>俯仰角，单位 °（设备约定的欧拉角，默认 ENU 312 顺序）。</translation>
    </message>
    <message>
        <location line="-82"/>
        <source>Heading</source>
        <translation>航向</translation>
    </message>
    <message>
        <location line="+84"/>
        <source>Yaw (heading) angle, in degrees (Euler angles in the device&apos;s convention, ENU 312 by default).</source>
        <translation>航向角，单位 °（设备约定的欧拉角，默认 ENU 312 顺序）。</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Attitude quaternion, component %1 (body to the North-West-Up frame the module is set to), no unit.</source>
        <translation>姿态四元数的 %1 分量（载体系到模块所设的北西天坐标系），无单位。</translation>
    </message>
    <message>
        <location line="+2"/>
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
        <source>Device timestamp: the UTC time of day once a PPS input has aligned the module&apos;s clock (HI91, UTC_UNSYNC clear), otherwise ms since power-up.</source>
        <translation>设备时间戳：PPS 输入将模块时钟对齐后为当日 UTC 时间（HI91，UTC_UNSYNC 清除），否则为上电以来的毫秒数。</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>Heading from the latest NMEA heading sentence, in degrees clockwise from north: HDT true north, HDM magnetic north (an HEC495 with output content NMEA 0183 sends HDT).</source>
        <translation>最新一条 NMEA 航向语句给出的航向，单位度，自北顺时针：HDT 为真北，HDM 为磁北（输出内容设为 NMEA 0183 的 HEC495 发送 HDT）。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The compass&apos;s magnetic field along its X, Y and Z axes as a relative value without unit: the horizontal component of the field pointing north is 1 (HEC495 manual 2.5, the same on CAN).</source>
        <translation>罗盘沿 X、Y、Z 轴的磁场，为无量纲的相对值：指向北的水平分量为 1（HEC495 手册 2.5，CAN 上相同）。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Magnetic roll (magnetic tool face), in degrees: the roll from the magnetic field, meaningful when the pitch is near ±90° (HEC495 manual 2.5).</source>
        <translation>磁性横滚（磁性工具面），单位为度：由磁场得到的横滚角，俯仰接近 ±90° 时才有意义（HEC495 手册 2.5）。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>UTC date from the HI83 frame (bit 6), shown once GNSS time is known.</source>
        <translation>HI83 帧中的 UTC 日期（位 6），获得 GNSS 时间后显示。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ship motion frequency (HI83 bit 11): heave, surge, sway, in Hz.</source>
        <translation>船舶运动频率（HI83 位 11）：升沉、纵荡、横荡，单位 Hz。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Acceleration in the east-north-up frame from integrated navigation (HI83 bit 13): E, N, U, in m/s².</source>
        <translation>组合导航输出的东北天坐标系加速度（HI83 位 13）：东、北、天，单位 m/s²。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Heading solution state of the GNSS (HI83 bit 15, solq_heading), then in brackets its satellites.</source>
        <translation>GNSS 航向解状态（HI83 位 15，solq_heading），括号内为其使用的卫星数。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Speed from an external odometer (HI83 bit 16), in m/s.</source>
        <translation>外接里程计速度（HI83 位 16），单位 m/s。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Geoid undulation: height of the geoid above the ellipsoid (HI83 bit 17), in m.</source>
        <translation>高程异常：大地水准面相对椭球面的高度（HI83 位 17），单位 m。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Age of the RTK differential corrections (HI83 bit 18), in s.</source>
        <translation>RTK 差分龄期（HI83 位 18），单位 s。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The module&apos;s node ID, the same as its CAN ID, 1 to 127 (HI83 bit 19).</source>
        <translation>模块节点 ID，与 CAN ID 相同，1 至 127（HI83 位 19）。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Measurement updates the integrated navigation filter has made (HI83 bit 25), the counters that are not zero: grav gravity, mag magnetometer, pos GNSS position, vel GNSS velocity, dual dual-antenna heading, nhc non-holonomic constraint, zupt zero velocity, zaru zero angular rate, zihr zero heading change, od odometer; a number for the reserved counters 10 to 15.</source>
        <translation>组合导航滤波器已进行的量测更新次数（HI83 位 25），只列出非零计数：grav 重力、mag 磁力计、pos GNSS 位置、vel GNSS 速度、dual 双天线航向、nhc 非完整约束、zupt 零速、zaru 零角速率、zihr 零航向变化、od 里程计；保留计数 10 至 15 以编号显示。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Accelerometer bias the navigation filter estimates (HI83 bit 26): X, Y, Z, in m/s².</source>
        <translation>导航滤波器估计的加速度零偏（HI83 位 26）：X、Y、Z，单位 m/s²。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Gyroscope bias the navigation filter estimates (HI83 bit 27): X, Y, Z, in rad/s.</source>
        <translation>导航滤波器估计的陀螺零偏（HI83 位 27）：X、Y、Z，单位 rad/s。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>GNSS accuracy (HI83 bit 28): norm of the position standard deviation in m, of the velocity standard deviation in m/s.</source>
        <translation>GNSS 精度（HI83 位 28）：位置标准差范数，单位 m；速度标准差范数，单位 m/s。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Dual-antenna GNSS heading (HI83 bit 29): baseline length in m, pitch and heading in degrees.</source>
        <translation>双天线 GNSS 航向（HI83 位 29）：基线长度，单位 m；俯仰角和航向角，单位度。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Raw GNSS position (HI83 bit 30): latitude and longitude in degrees, height above mean sea level in m.</source>
        <translation>GNSS 原始位置（HI83 位 30）：纬度和经度，单位度；海拔高度，单位 m。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Raw GNSS velocity (HI83 bit 31): east, north, up, in m/s.</source>
        <translation>GNSS 原始速度（HI83 位 31）：东、北、天，单位 m/s。</translation>
    </message>
    <message>
        <location line="-54"/>
        <source>Integrated navigation state: 0 invalid, 1 aligning, 3 navigating, 6 dead reckoning.</source>
        <translation>组合导航解状态：0 解无效，1 对准中，3 组合导航中，6 惯性递推中。</translation>
    </message>
    <message numerus="yes">
        <location line="-362"/>
        <source>No new value for %n s: the device stopped sending this quantity (another output content, a polled record that stopped, or a link that went quiet).</source>
        <translation>
            <numerusform>%n 秒内无新值：设备已停止发送该量（输出内容已更改、轮询记录已停止，或链路已静默）。</numerusform>
        </translation>
    </message>
    <message>
        <location line="+364"/>
        <source>Position from integrated navigation, in degrees (south and west negative).</source>
        <translation>组合导航解算的位置，单位 °（南纬和西经为负）。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Height above mean sea level, in m.</source>
        <translation>平均海平面以上的高度，单位 m。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Velocity in the east-north-up frame, in m/s.</source>
        <translation>东北天（ENU）坐标系下的速度，单位 m/s。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>GNSS fix quality as in NMEA GGA, then in brackets the satellites used, from the latest GGA or SXT sentence.</source>
        <translation>GNSS 定位质量（与 NMEA GGA 相同），括号内为使用的卫星数，取自最新的 GGA 或 SXT 语句。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>UTC time of day from the latest NMEA sentence (GGA, RMC or SXT), hh:mm:ss.ss.</source>
        <translation>取自最新 NMEA 语句（GGA、RMC 或 SXT）的 UTC 当日时间，格式 hh:mm:ss.ss。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Ship motion displacement (heave, surge, sway), in m.</source>
        <translation>船舶运动位移（垂荡、纵荡、横荡），单位 m。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Inclinometer angle about the %1 axis, in degrees.</source>
        <translation>倾角仪绕 %1 轴的角度，单位 °。</translation>
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
    <name>imudesk::models::RegisterTableModel</name>
    <message>
        <location filename="../core/itemmodels/register_table_model.cpp" line="+146"/>
        <source>Address</source>
        <translation>地址</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Name</source>
        <translation>名称</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Type</source>
        <translation>类型</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Access</source>
        <translation>读写权限</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Raw</source>
        <translation>原始值</translation>
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
        <location line="+1"/>
        <source>Description</source>
        <translation>说明</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>%1 is not a valid value for %2: %3</source>
        <translation>%1 不是 %2 的有效值：%3</translation>
    </message>
</context>
<context>
    <name>imudesk::models::SettingsTableModel</name>
    <message>
        <location filename="../core/itemmodels/settings_table_model.cpp" line="+61"/>
        <source>unknown setting &apos;%1&apos;</source>
        <translation>未知设置项“%1”</translation>
    </message>
    <message>
        <location line="+66"/>
        <source>Key: %1</source>
        <translation>键名：%1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Takes effect: %1</source>
        <translation>生效条件：%1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Read back by: %1</source>
        <translation>回读方式：%1</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>read the device first</source>
        <translation>请先读取设备</translation>
    </message>
    <message>
        <location line="+42"/>
        <source>Setting</source>
        <translation>设置项</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Key</source>
        <translation>键名</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>On the device</source>
        <translation>设备当前值</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>New value</source>
        <translation>新值</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Takes effect</source>
        <translation>生效条件</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Read back by</source>
        <translation>回读方式</translation>
    </message>
</context>
<context>
    <name>imudesk::plot::Channel</name>
    <message>
        <location filename="../core/plot/channel_catalog.cpp" line="+18"/>
        <location line="+1"/>
        <location line="+1"/>
        <source>Acceleration %1</source>
        <translation>加速度 %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+1"/>
        <location line="+1"/>
        <source>Angular velocity %1</source>
        <translation>角速度 %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+1"/>
        <location line="+1"/>
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
        <location line="+1"/>
        <location line="+1"/>
        <location line="+1"/>
        <location line="+1"/>
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
        <location line="+1"/>
        <location line="+1"/>
        <source>Relative magnetic field %1</source>
        <translation>相对磁场 %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Magnetic roll</source>
        <translation>磁性横滚</translation>
    </message>
</context>
<context>
    <name>imudesk::record::ReplayWorker</name>
    <message>
        <location filename="../core/record/replay_worker.cpp" line="+48"/>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>%1: %2. Replaying what is intact.</source>
        <translation>%1：%2。将回放完好的部分。</translation>
    </message>
    <message numerus="yes">
        <location line="+3"/>
        <source>%n damaged chunk(s) skipped</source>
        <translation>
            <numerusform>已跳过 %n 个损坏的数据块</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>imudesk::results::ResultsStore</name>
    <message>
        <location filename="../core/results/results_store.cpp" line="+267"/>
        <source>Updating the results database %1 to schema %2 failed: %3</source>
        <translation>将结果数据库 %1 升级到架构 %2 失败：%3</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>Qt&apos;s PostgreSQL driver is not installed (on Debian: the package libqt6sql6-psql).</source>
        <translation>未安装 Qt 的 PostgreSQL 驱动（Debian 上为软件包 libqt6sql6-psql）。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Qt&apos;s SQLite driver is not installed (on Debian: the package libqt6sql6-sqlite).</source>
        <translation>未安装 Qt 的 SQLite 驱动（Debian 上为软件包 libqt6sql6-sqlite）。</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>Cannot open the results database %1: %2</source>
        <translation>无法打开结果数据库 %1：%2</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>%1 was written by a newer ImuDesk (schema %2; this one knows %3): update ImuDesk to use it</source>
        <translation>%1 由更新版本的 ImuDesk 写入（模式 %2；本版本支持 %3）：请更新 ImuDesk 后再使用</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The results database %1 has schema %2, this ImuDesk needs %3: have its owner run &quot;imudesk-cli results setup&quot; on it.</source>
        <translation>结果数据库 %1 的架构为 %2，本 ImuDesk 需要 %3：请让其所有者对它运行 “imudesk-cli results setup”。</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>the results database is not open</source>
        <translation>结果数据库未打开</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Storing the result of %1 in %2 failed: %3. It is still in the run folder.</source>
        <translation>将 %1 的结果存入 %2 失败：%3。结果仍保存在运行文件夹中。</translation>
    </message>
    <message>
        <location line="+46"/>
        <source>Storing results in %1 failed: %2. They are still in the run folder.</source>
        <translation>将结果存入 %1 失败：%2。结果仍保存在运行文件夹中。</translation>
    </message>
    <message>
        <location line="+320"/>
        <source>Roles are a PostgreSQL server&apos;s; %1 is an SQLite file.</source>
        <translation>角色属于 PostgreSQL 服务器；%1 是 SQLite 文件。</translation>
    </message>
</context>
<context>
    <name>imudesk::results::ResultsUploader</name>
    <message>
        <location filename="../core/results/results_uploader.cpp" line="+28"/>
        <source>%1 is gone from the station; its record keeps the station&apos;s path</source>
        <translation>%1 已不在测试站上；其记录保留测试站上的路径</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Cannot create %1 in the shared artifact folder: check that it is mounted and writable.</source>
        <translation>无法在共享附件文件夹中创建 %1：请检查它已挂载且可写。</translation>
    </message>
    <message>
        <location line="+5"/>
        <location line="+10"/>
        <source>Cannot copy %1 to %2: check that the shared folder is mounted and has room.</source>
        <translation>无法将 %1 复制到 %2：请检查共享文件夹已挂载且有足够空间。</translation>
    </message>
    <message>
        <location line="-5"/>
        <source>The copy of %1 in the shared folder does not match its SHA-256; it will be copied again.</source>
        <translation>共享文件夹中 %1 的副本与其 SHA-256 不符；将重新复制。</translation>
    </message>
</context>
<context>
    <name>imudesk::settings::ConfigurationController</name>
    <message>
        <location filename="../core/settings/configuration_controller.cpp" line="+24"/>
        <source>verified</source>
        <translation>已验证</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not taken (read back differs)</source>
        <translation>未生效（回读值不同）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>refused (ERR)</source>
        <translation>被拒绝（ERR）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no reply</source>
        <translation>无应答</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not sent</source>
        <translation>未发送</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>the device has not been read yet (its model and firmware decide which settings exist)</source>
        <translation>尚未读取设备（设备型号和固件决定有哪些设置项）</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>unknown setting &apos;%1&apos; (settings: %2)</source>
        <translation>未知设置项“%1”（可用设置项：%2）</translation>
    </message>
    <message>
        <location line="+18"/>
        <location line="+274"/>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <location line="-172"/>
        <source>the device did not tell its model and firmware (LOG VERSION: %1)</source>
        <translation>设备未报告其型号和固件版本（LOG VERSION：%1）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>incomplete reply</source>
        <translation>应答不完整</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>LOG COMCONFIG failed (%1): the settings shown may be out of date</source>
        <translation>LOG COMCONFIG 失败（%1）：显示的设置可能不是最新的</translation>
    </message>
    <message>
        <location line="+18"/>
        <location line="+13"/>
        <location line="+129"/>
        <source>another configuration step is still running</source>
        <translation>另一个配置步骤仍在进行</translation>
    </message>
    <message>
        <location line="-75"/>
        <location line="+97"/>
        <source>the device answered %1</source>
        <translation>设备应答 %1</translation>
    </message>
    <message>
        <location line="-79"/>
        <source>an empty reply</source>
        <translation>空应答</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>the module did not answer the read-back (%1); check it with LOG COMCONFIG</source>
        <translation>模块未应答读回（%1）；请用 LOG COMCONFIG 检查</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>LOG COMCONFIG did not report %1 in a form ImuDesk reads; the reply was: %2</source>
        <translation>LOG COMCONFIG 未以 ImuDesk 能读取的形式报告 %1；应答为：%2</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the device reports %1</source>
        <translation>设备报告 %1</translation>
    </message>
    <message>
        <location line="-267"/>
        <source>could not be read back</source>
        <translation>无法回读</translation>
    </message>
    <message>
        <location line="+298"/>
        <source>unknown action &apos;%1&apos;</source>
        <translation>未知操作“%1”</translation>
    </message>
</context>
<context>
    <name>imudesk::settings::ProfileBatch</name>
    <message>
        <location filename="../core/settings/profile_batch.cpp" line="+50"/>
        <source>cannot connect: %1</source>
        <translation>无法连接：%1</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>SAVECONFIG failed: %1</source>
        <translation>SAVECONFIG 失败：%1</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>%1=%2 not applied: %3</source>
        <translation>%1=%2 未应用：%3</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>%1=%2: %3 %4</source>
        <translation>%1=%2：%3 %4</translation>
    </message>
</context>
<context>
    <name>imudesk::sim::CanSimulator</name>
    <message>
        <location filename="../core/sim/can_simulator.cpp" line="+46"/>
        <source>cannot create CAN device %1:%2: %3</source>
        <translation>无法创建 CAN 设备 %1:%2：%3</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>cannot open CAN device %1:%2: %3</source>
        <translation>无法打开 CAN 设备 %1:%2：%3</translation>
    </message>
    <message>
        <location line="+100"/>
        <source>--can needs PLUGIN:INTERFACE, e.g. virtualcan:can0</source>
        <translation>--can 需要 PLUGIN:INTERFACE 格式的参数，例如 virtualcan:can0</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>--protocol must be j1939 or canopen</source>
        <translation>--protocol 只能是 j1939 或 canopen</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>--device must be hipnuc or hec495</source>
        <translation>--device 只能是 hipnuc 或 hec495</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>--node must be 1..127</source>
        <translation>--node 必须为 1..127</translation>
    </message>
</context>
<context>
    <name>imudesk::sim::SimulatedTransport</name>
    <message>
        <location filename="../core/sim/simulated_transport.cpp" line="+86"/>
        <source>The connection to %1 was lost (simulated unplug). Check the cable; everything received so far is kept.</source>
        <translation>与 %1 的连接已断开（模拟拔出）。请检查线缆；已收到的数据全部保留。</translation>
    </message>
</context>
<context>
    <name>imudesk::station::ModuleRunner</name>
    <message>
        <location filename="../core/station/module_runner.cpp" line="+85"/>
        <source>the module did not answer on %1 within %2 s: check the cable, the power and the port</source>
        <translation>模块在 %2 s 内未在 %1 上应答：请检查线缆、电源和串口</translation>
    </message>
    <message>
        <location line="+40"/>
        <source>the module&apos;s settings could not be read: %1</source>
        <translation>无法读取模块的设置：%1</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>updated from %1 to %2 and verified</source>
        <translation>已从 %1 升级到 %2 并校验通过</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>after the update the module reports firmware %1, older than %2</source>
        <translation>升级后模块报告的固件为 %1，低于 %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+234"/>
        <location line="+1"/>
        <source>(none)</source>
        <translation>（无）</translation>
    </message>
    <message>
        <location line="-217"/>
        <source>could not connect to %1: %2</source>
        <translation>无法连接到 %1：%2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the module disappeared during &quot;%1&quot; (%2): check its cable; the other modules go on</source>
        <translation>模块在“%1”期间断开（%2）：请检查其线缆；其他模块继续测试</translation>
    </message>
    <message>
        <location line="+89"/>
        <source>%1; marginal: %2</source>
        <translation>%1；临界：%2</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>not run: &quot;%1&quot; failed</source>
        <translation>未运行：“%1”失败</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>disabled in the plan</source>
        <translation>计划中已停用</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>cancelled by the operator</source>
        <translation>已由操作员取消</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>%1 (marginal &gt; %2)</source>
        <translation>%1（临界 &gt; %2）</translation>
    </message>
    <message>
        <location line="+39"/>
        <source>%1, firmware %2, serial %3</source>
        <translation>%1，固件 %2，序列号 %3</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>(no product name)</source>
        <translation>（无产品型号）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1: not one of %2</source>
        <translation>%1：不属于 %2</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1: firmware outside %2 … %3</source>
        <translation>%1：固件不在 %2 … %3 范围内</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+1"/>
        <source>any</source>
        <translation>不限</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>the plan&apos;s minimum firmware &quot;%1&quot; is not a version</source>
        <translation>测试计划中的最低固件“%1”不是有效的版本号</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>firmware %1 is at least %2: no update needed</source>
        <translation>固件 %1 不低于 %2：无需升级</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>firmware %1 is older than %2 and the plan names no image to update from</source>
        <translation>固件 %1 低于 %2，且测试计划未指定用于升级的固件镜像</translation>
    </message>
    <message>
        <location line="+6"/>
        <location line="+5"/>
        <source>%1: %2 (nothing was sent to the module)</source>
        <translation>%1：%2（未向模块发送任何数据）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>updating from %1 …</source>
        <translation>正在从 %1 升级…</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>the update failed: %1</source>
        <translation>升级失败：%1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>the module did not come back after the update within %1 s</source>
        <translation>升级后模块未在 %1 s 内恢复连接</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the updater could not start</source>
        <translation>无法启动升级程序</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>profile %1: %2</source>
        <translation>配置方案 %1：%2</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1=%2 (%3)</source>
        <translation>%1=%2（%3）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the module cannot take: %1</source>
        <translation>模块无法接受：%1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the module already holds every setting of the profile</source>
        <translation>模块已具有配置方案中的全部设置</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>%1=%2: %3 %4</source>
        <translation>%1=%2：%3 %4</translation>
    </message>
    <message numerus="yes">
        <location line="+11"/>
        <source>%n setting(s) applied and read back</source>
        <translation>
            <numerusform>已应用并回读 %n 项设置</numerusform>
        </translation>
    </message>
    <message>
        <location line="+14"/>
        <source>SAVECONFIG answered OK</source>
        <translation>SAVECONFIG 已应答 OK</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>SAVECONFIG failed: %1</source>
        <translation>SAVECONFIG 失败：%1</translation>
    </message>
    <message>
        <location line="+43"/>
        <source>no data from the module for %1 s during &quot;%2&quot;: is its output on, is it still connected?</source>
        <translation>“%2”期间 %1 s 未收到模块数据：模块输出是否已开启？是否仍在连接中？</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>only %1 samples in %2 s: enable the module&apos;s output (HI91, at least 10 Hz)</source>
        <translation>%2 s 内仅有 %1 个样本：请开启模块的输出（HI91，至少 10 Hz）</translation>
    </message>
    <message>
        <location line="+39"/>
        <source>cannot judge: %1 (%2). Keep the module still on the fixture and test it again.</source>
        <translation>无法判定：%1（%2）。请让模块在夹具上保持静止后重新测试。</translation>
    </message>
    <message>
        <location line="+40"/>
        <source>%1 samples within every limit</source>
        <translation>%1 个样本，均在限值内</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1 samples; values outside the limits are marked</source>
        <translation>%1 个样本；超出限值的数值已标出</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>%1 s of data do not reach τ = %2 s: measure for at least %3 s</source>
        <translation>%1 s 的数据不足以达到 τ = %2 s：请至少测量 %3 s</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>σ(%1 s) of each gyro axis</source>
        <translation>陀螺仪各轴的 σ(%1 s)</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>the module&apos;s output carries no Euler angles: enable HI91 in the profile</source>
        <translation>模块输出中没有欧拉角：请在配置方案中启用 HI91</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>mounted as expected</source>
        <translation>安装方向符合预期</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>roll %1°, pitch %2°: the module is not mounted as the plan expects</source>
        <translation>横滚角 %1°，俯仰角 %2°：模块的安装方向与测试计划不符</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>the module reported no firmware version, so the calibration commands are unknown</source>
        <translation>模块未报告固件版本，因此无法确定校准指令</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>the calibration did not end within %1 s</source>
        <translation>校准未在 %1 s 内结束</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>the turns did not end within %1 s: is the module on the turntable?</source>
        <translation>转动未在 %1 s 内结束：模块是否已放在转台上？</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>no run folder to record into</source>
        <translation>没有可供记录的运行文件夹</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>the recording stopped: %1</source>
        <translation>记录已停止：%1</translation>
    </message>
    <message>
        <location filename="../core/station/module_runner_verify.cpp" line="+42"/>
        <source>cannot judge: %1</source>
        <translation>无法判定：%1</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>%1 poses; %2</source>
        <translation>%1 个姿态；%2</translation>
    </message>
</context>
<context>
    <name>imudesk::station::RunFolder</name>
    <message>
        <location filename="../core/station/run_folder.cpp" line="+35"/>
        <source>cannot write %1: %2. Free some space or choose another report folder.</source>
        <translation>无法写入 %1：%2。请释放一些空间或选择其他报告文件夹。</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>cannot create the report folder %1: choose a folder you may write to</source>
        <translation>无法创建报告文件夹 %1：请选择有写入权限的文件夹</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1 holds a run of another plan; choose a new folder so that results stay comparable</source>
        <translation>%1 中已有其他测试计划的运行结果；请选择新文件夹，以保证结果可比</translation>
    </message>
    <message>
        <location line="+99"/>
        <source>Cannot write %1: %2. The result is in the results database and the summaries.</source>
        <translation>无法写入 %1：%2。结果已保存在结果数据库和汇总文件中。</translation>
    </message>
</context>
<context>
    <name>imudesk::station::StationSession</name>
    <message>
        <location filename="../core/station/station_session.cpp" line="+81"/>
        <source>The plan %1 could not be opened: %2</source>
        <translation>无法打开测试计划 %1：%2</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Wait for the run to end, or cancel it, before changing the simulated tray.</source>
        <translation>请等待运行结束或将其取消，然后再更改模拟托盘。</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>a good module</source>
        <translation>正常模块</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>a noisy gyro (%1 times the noise)</source>
        <translation>陀螺仪噪声过大（噪声为正常的 %1 倍）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>mounted wrongly (on its side, roll %1°)</source>
        <translation>安装方向错误（侧放，横滚 %1°）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>old firmware</source>
        <translation>旧版固件</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>The simulated modules could not start: %1</source>
        <translation>模拟模块无法启动：%1</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Simulated HI14 %1 of %2, firmware %3: %4</source>
        <translation>模拟 HI14（第 %1 个，共 %2 个），固件 %3：%4</translation>
    </message>
    <message>
        <location line="+74"/>
        <source>Open a test plan first (Open…), or start from the example.</source>
        <translation>请先打开测试计划（“打开…”），或从示例新建。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The plan &quot;%1&quot; cannot run:
• %2
Edit it (Edit…) and start again.</source>
        <translation>测试计划“%1”无法运行：
• %2
请编辑该计划（“编辑…”）后重新开始。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Check the ports of the modules to test first.</source>
        <translation>请先勾选待测模块的串口。</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>The report folder cannot be used: %1</source>
        <translation>报告文件夹无法使用：%1</translation>
    </message>
    <message>
        <location line="+72"/>
        <source>No run yet.</source>
        <translation>尚未运行。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 passed · %2 failed · %3 running · %4 waiting</source>
        <translation>%1 通过 · %2 失败 · %3 运行中 · %4 等待</translation>
    </message>
    <message>
        <location line="+12"/>
        <source> — the workspace of %1 opens when its test has ended</source>
        <translation> — %1 的工作区将在其测试结束后打开</translation>
    </message>
    <message>
        <location line="+1"/>
        <source> — the workspaces of %1 open when their tests have ended</source>
        <translation> — %1 的工作区将在各自测试结束后打开</translation>
    </message>
</context>
<context>
    <name>imudesk::station::TestPlan</name>
    <message>
        <location filename="../core/station/test_plan.cpp" line="+99"/>
        <source>Identify</source>
        <translation>识别</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Firmware version</source>
        <translation>固件版本</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Apply profile</source>
        <translation>应用配置方案</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Static noise and bias</source>
        <translation>静态噪声和零偏</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Allan deviation</source>
        <translation>阿伦方差</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Attitude (mounting)</source>
        <translation>姿态（安装方向）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Magnetometer calibration</source>
        <translation>地磁校准</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Gyro scale factor</source>
        <translation>陀螺仪标度因数</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Verify module</source>
        <translation>验证模块</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save configuration</source>
        <translation>保存配置</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Record evidence</source>
        <translation>证据记录</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>The module reports an expected product and a firmware version within the range.</source>
        <translation>模块报告的产品型号符合预期，固件版本在范围内。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Firmware older than the minimum is updated from the image and verified; newer passes as it is.</source>
        <translation>低于最低版本的固件将用固件镜像升级并校验；不低于该版本的直接通过。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The profile&apos;s settings are applied and every one is read back.</source>
        <translation>应用配置方案中的设置，并逐项回读。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>At rest: per-axis standard deviation and mean of the gyro, accelerometer noise and the gravity magnitude against their limits.</source>
        <translation>静止状态下：将陀螺仪各轴的标准差和均值、加速度计噪声以及重力幅值与各自的限值比较。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The gyro&apos;s Allan deviation at the averaging time, worst axis, below the limit.</source>
        <translation>陀螺仪在该平均时间下的阿伦方差（取最差轴）低于限值。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Roll and pitch at rest within the tolerance of the expected orientation: the module is mounted as intended.</source>
        <translation>静止时横滚角和俯仰角与预期姿态的偏差在容差内：模块按预期方向安装。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The module&apos;s own magnetometer calibration (MCAL) runs to the end and succeeds; the module must be turned through every attitude meanwhile (a rotation fixture).</source>
        <translation>模块自身的地磁校准（MCAL）运行完毕并成功；期间必须将模块转过所有姿态（使用旋转工装）。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>On a turntable: two turns each way; the gyro&apos;s scale-factor error below the limit.</source>
        <translation>在转台上：正反方向各转两圈；陀螺仪标度因数误差低于限值。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Turned through at least 9 still poses (by hand or a fixture): the accelerometer&apos;s bias and scale, the gyro&apos;s bias and scale and the attitude&apos;s tilt and heading, each within its limit.</source>
        <translation>依次转到至少 9 个静止姿态（手持或用夹具）：加速度计的零偏和标度因数、陀螺仪的零偏和标度因数以及姿态的倾角和航向，各自在限值之内。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>SAVECONFIG: the module keeps its settings after a restart.</source>
        <translation>SAVECONFIG：模块重启后保留其设置。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The module&apos;s output is recorded into the run folder as evidence.</source>
        <translation>将模块的输出记录到运行文件夹中作为证据。</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Products</source>
        <translation>产品型号</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Product names the module may report, separated by commas (HI14 matches HI14R3)</source>
        <translation>模块可报告的产品型号，以逗号分隔（HI14 可匹配 HI14R3）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Lowest firmware</source>
        <translation>最低固件版本</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Oldest firmware accepted, e.g. 1.6.6; empty: any</source>
        <translation>可接受的最低固件版本，例如 1.6.6；留空：不限</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Highest firmware</source>
        <translation>最高固件版本</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Newest firmware accepted; empty: any</source>
        <translation>可接受的最高固件版本；留空：不限</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>At least</source>
        <translation>最低版本</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Modules with older firmware are updated</source>
        <translation>固件低于此版本的模块将被升级</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Image</source>
        <translation>固件镜像</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Intel HEX or binary image, relative to the plan&apos;s folder; without one an older module fails this step</source>
        <translation>Intel HEX 或二进制镜像，路径相对于测试计划所在文件夹；未指定时，固件较旧的模块在此步骤失败</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Profile</source>
        <translation>配置方案</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Configuration profile (.json, saved from the profile dialog), relative to the plan&apos;s folder</source>
        <translation>配置方案（.json，从配置方案对话框保存），路径相对于测试计划所在文件夹</translation>
    </message>
    <message>
        <location line="+6"/>
        <location line="+20"/>
        <location line="+21"/>
        <location line="+17"/>
        <location line="+28"/>
        <source>Duration</source>
        <translation>时长</translation>
    </message>
    <message>
        <location line="-85"/>
        <source>How long the module is measured at rest</source>
        <translation>模块静止测量的时长</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Gyro noise max</source>
        <translation>陀螺仪噪声上限</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Largest standard deviation of each gyro axis</source>
        <translation>陀螺仪各轴标准差的最大允许值</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+66"/>
        <source>Gyro bias max</source>
        <translation>陀螺仪零偏上限</translation>
    </message>
    <message>
        <location line="-65"/>
        <source>Largest magnitude of each gyro axis&apos;s mean at rest</source>
        <translation>静止时陀螺仪各轴均值绝对值的最大允许值</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Accelerometer noise max</source>
        <translation>加速度计噪声上限</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Largest standard deviation of each accelerometer axis</source>
        <translation>加速度计各轴标准差的最大允许值</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Gravity tolerance</source>
        <translation>重力容差</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The mean acceleration&apos;s magnitude may differ from 1 G by this much</source>
        <translation>平均加速度的幅值与 1 G 之差允许的最大值</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>How long the module is measured at rest (at least 10 averaging times)</source>
        <translation>模块静止测量的时长（至少为平均时间的 10 倍）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Averaging time</source>
        <translation>平均时间</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>τ at which the Allan deviation is read</source>
        <translation>读取阿伦方差所用的 τ</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>σ(τ) max</source>
        <translation>σ(τ) 上限</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Largest Allan deviation of any gyro axis at τ</source>
        <translation>陀螺仪任一轴在 τ 处阿伦方差的最大允许值</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Expected roll</source>
        <translation>预期横滚角</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Roll of the module in its fixture (Z up: 0)</source>
        <translation>模块在工装中的横滚角（Z 轴朝上：0）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Expected pitch</source>
        <translation>预期俯仰角</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Pitch of the module in its fixture (Z up: 0)</source>
        <translation>模块在工装中的俯仰角（Z 轴朝上：0）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Tolerance</source>
        <translation>容差</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Largest difference of roll and of pitch</source>
        <translation>横滚角和俯仰角各自允许的最大偏差</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The angles are averaged over this time</source>
        <translation>在此时长内对角度取平均</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+8"/>
        <source>Time limit</source>
        <translation>时间限值</translation>
    </message>
    <message>
        <location line="-7"/>
        <source>The calibration fails when it has not ended by then</source>
        <translation>到时仍未结束则校准失败</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Scale error max</source>
        <translation>标度因数误差上限</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Largest scale-factor error of the Z gyro</source>
        <translation>Z 轴陀螺仪标度因数误差的最大允许值</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The run fails when the turns have not ended by then</source>
        <translation>到时转动仍未结束则本次测试失败</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>How long the module is turned through its poses (3 s still in each, at least 9)</source>
        <translation>模块依次转过各姿态的时长（每个姿态静止 3 s，至少 9 个）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Local gravity</source>
        <translation>当地重力</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The station&apos;s gravity (m/s²); 0: standard gravity assumed, with its uncertainty</source>
        <translation>工位的重力（m/s²）；0：假定为标准重力，并计入其不确定度</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Accelerometer bias max</source>
        <translation>加速度计零偏上限</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Largest accelerometer bias of any axis</source>
        <translation>任一轴加速度计零偏的最大值</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Accelerometer scale error max</source>
        <translation>加速度计标度因数误差上限</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Largest accelerometer scale error of any axis</source>
        <translation>任一轴加速度计标度因数误差的最大值</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Largest gyro bias of any axis</source>
        <translation>任一轴陀螺仪零偏的最大值</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Gyro scale error max</source>
        <translation>陀螺仪标度因数误差上限</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Largest gyro scale error of any axis</source>
        <translation>任一轴陀螺仪标度因数误差的最大值</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Tilt error max</source>
        <translation>倾角误差上限</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Largest roll or pitch error of the module&apos;s attitude</source>
        <translation>模块姿态横滚或俯仰误差的最大值</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Heading error max</source>
        <translation>航向误差上限</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Largest heading error of the module&apos;s attitude (needs a magnetometer)</source>
        <translation>模块姿态航向误差的最大值（需要磁力计）</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>How long the module&apos;s output is recorded</source>
        <translation>记录模块输出的时长</translation>
    </message>
    <message>
        <location line="+64"/>
        <location line="+26"/>
        <source>%1 has no parameter &quot;%2&quot;</source>
        <translation>%1 没有参数“%2”</translation>
    </message>
    <message>
        <location line="-23"/>
        <source>&quot;%1&quot; must be a text</source>
        <translation>“%1”必须是文本</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&quot;%1&quot; must be a firmware version such as 1.7.1, not &quot;%2&quot;</source>
        <translation>“%1”必须是固件版本号（如 1.7.1），而不是“%2”</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&quot;%1&quot; must be a number</source>
        <translation>“%1”必须是数字</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&quot;%1&quot; = %2 is outside %3 … %4 %5</source>
        <translation>“%1” = %2 超出 %3 … %4 %5</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>&quot;%1&quot; is not a limit: it has no marginal band</source>
        <translation>“%1”不是限值：没有临界区间</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&quot;%1&quot;: &quot;marginal_high&quot; must be a number</source>
        <translation>“%1”：“marginal_high”必须是数字</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&quot;%1&quot;: &quot;marginal_high&quot; = %2 is outside %3 … %4%5</source>
        <translation>“%1”：“marginal_high” = %2 超出 %3 … %4%5</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>&quot;%1&quot;: &quot;marginal_high&quot; = %2%4 is not below the limit %3%4</source>
        <translation>“%1”：“marginal_high” = %2%4 不低于限值 %3%4</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>This plan was written in format version %1; it is converted to version %2 and will be saved as version %2.</source>
        <translation>此测试计划以格式版本 %1 编写；已转换为版本 %2，并将以版本 %2 保存。</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>the plan is larger than %1 KiB</source>
        <translation>测试计划大于 %1 KiB</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>not JSON: %1 at byte %2</source>
        <translation>不是 JSON：第 %2 字节处：%1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>not a station plan (&quot;format&quot; is not &quot;%1&quot;)</source>
        <translation>不是生产测试台的测试计划（&quot;format&quot; 不是 &quot;%1&quot;）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>plan version %1 is not supported (this ImuDesk reads versions 1 to %2)</source>
        <translation>不支持测试计划版本 %1（本 ImuDesk 读取版本 1 至 %2）</translation>
    </message>
    <message>
        <location line="+8"/>
        <location line="+118"/>
        <source>the plan has no steps</source>
        <translation>测试计划中没有步骤</translation>
    </message>
    <message>
        <location line="-112"/>
        <source>step %1: unknown step &quot;%2&quot;</source>
        <translation>步骤 %1：未知步骤“%2”</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>step %1 (%2): &quot;enabled&quot; must be true or false</source>
        <translation>步骤 %1（%2）：&quot;enabled&quot; 必须为 true 或 false</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>step %1 (%2): &quot;%3&quot; has an unknown field &quot;%4&quot; (a limit is a number or {&quot;high&quot;: …, &quot;marginal_high&quot;: …})</source>
        <translation>步骤 %1（%2）：“%3”含有未知字段“%4”（限值应为数字或 {&quot;high&quot;: …, &quot;marginal_high&quot;: …}）</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>step %1 (%2): &quot;%3&quot; has no &quot;high&quot; (the limit itself)</source>
        <translation>步骤 %1（%2）：“%3”缺少“high”（限值本身）</translation>
    </message>
    <message>
        <location line="+9"/>
        <location line="+3"/>
        <location line="+80"/>
        <location line="+4"/>
        <source>step %1 (%2): %3</source>
        <translation>步骤 %1（%2）：%3</translation>
    </message>
    <message>
        <location line="-42"/>
        <source>cannot open %1: %2</source>
        <translation>无法打开 %1：%2</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>cannot write %1: %2. Choose another folder or free some space.</source>
        <translation>无法写入 %1：%2。请选择其他文件夹或释放一些空间。</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>step %1 (%2): no %3 file given</source>
        <translation>步骤 %1（%2）：未指定 %3 文件</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>step %1 (%2): %3 not found</source>
        <translation>步骤 %1（%2）：找不到 %3</translation>
    </message>
</context>
<context>
    <name>imudesk::station::Verdict</name>
    <message>
        <location filename="../core/station/station_result.cpp" line="+24"/>
        <source>waiting</source>
        <translation>等待中</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>running</source>
        <translation>运行中</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>pass</source>
        <translation>通过</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>fail</source>
        <translation>失败</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>skipped</source>
        <translation>已跳过</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::AnalysisWindow</name>
    <message>
        <location filename="../ui/charts/analysis_window.cpp" line="+33"/>
        <source>Analysis</source>
        <translation>分析</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Channel</source>
        <translation>通道</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Unit</source>
        <translation>单位</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Mean</source>
        <translation>均值</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Std. dev.</source>
        <translation>标准差</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Min</source>
        <translation>最小值</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Max</source>
        <translation>最大值</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Frame intervals (device clock)</source>
        <translation>帧间隔（设备时钟）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Allan deviation</source>
        <translation>阿伦方差</translation>
    </message>
    <message>
        <location line="+53"/>
        <source>Analysing %1…</source>
        <translation>正在分析 %1…</translation>
    </message>
    <message>
        <location line="+42"/>
        <source>%1: %2 frames over %3 s, output rate %4 Hz, interval %5 ± %6 ms, frames lost %7</source>
        <translation>%1：%3 s 内共 %2 帧，输出频率 %4 Hz，帧间隔 %5 ± %6 ms，丢帧 %7</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Allan deviation: %1 (%2)</source>
        <translation>阿伦方差：%1（%2）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Allan deviation σ(τ): deg/s for gyro, G for acc</source>
        <translation>阿伦方差 σ(τ)：陀螺仪为 deg/s，加速度计为 G</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Allan deviation: %1</source>
        <translation>阿伦方差：%1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>no noise to measure: its values never change (below the file&apos;s resolution, or a constant column)</source>
        <translation>无噪声可测：数值从不变化（低于文件的分辨率，或为常数列）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>ARW %1 deg/√h</source>
        <translation>ARW %1 deg/√h</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>VRW %1 m/s/√h</source>
        <translation>VRW %1 m/s/√h</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>bias instability %1 deg/h at τ = %2 s</source>
        <translation>零偏不稳定性 %1 deg/h（τ = %2 s）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>bias instability %1 mG at τ = %2 s</source>
        <translation>零偏不稳定性 %1 mG（τ = %2 s）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Recommended minimum recording length for τ up to %1 s: %2 h</source>
        <translation>τ 最大到 %1 s 时建议的最短记录时长：%2 h</translation>
    </message>
    <message>
        <location line="+14"/>
        <location line="+33"/>
        <source>frames</source>
        <translation>帧数</translation>
    </message>
    <message numerus="yes">
        <location line="-15"/>
        <source>%1 to %2 ms: %n frame(s)</source>
        <translation>
            <numerusform>%1 至 %2 ms：%n 帧</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+3"/>
        <source>%1 ms or more: %n frame(s)</source>
        <translation>
            <numerusform>%1 ms 及以上：%n 帧</numerusform>
        </translation>
    </message>
    <message>
        <location line="+37"/>
        <source>interval, ms</source>
        <translation>帧间隔（ms）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>interval, ms (the last bar: %1 ms or more)</source>
        <translation>间隔，ms（最后一柱：%1 ms 及以上）</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>τ, s</source>
        <translation>τ（s）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>σ(τ)</source>
        <translation>σ(τ)</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::AttitudeResetWizard</name>
    <message>
        <location filename="../ui/calibration/attitude_reset_wizard.cpp" line="+23"/>
        <source>Heading reset: the current heading becomes 0. Keep the module still. (Firmware 1.7.1 and later.)</source>
        <translation>航向角清零：当前航向角变为 0。请保持模块静止。（固件 1.7.1 及以上版本。）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Relative zero: the current pitch and roll become 0, whatever they are. Keep the module still in the pose that should read level. CONFIG ATT RST 5 undoes it.</source>
        <translation>相对置零：无论当前俯仰角和横滚角是多少，都将其变为 0。请让模块静止在应显示为水平的姿态。CONFIG ATT RST 5 可撤销此操作。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Auto level: only when the module lies nearly level (pitch and roll within 5 deg), or upside down (roll within 5 deg of 180): it is levelled to 0/0 or 0/180. Permanent: RST 5 does not undo it. Keep the module still.</source>
        <translation>自动调平：仅当模块接近水平（俯仰角和横滚角均在 5 deg 以内）或倒置（横滚角与 180 相差 5 deg 以内）时可用：模块被调平为 0/0 或 0/180。永久生效：RST 5 无法撤销。请保持模块静止。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Cancel levelling: clears the relative pitch and roll set by RST 2; the absolute angles come back.</source>
        <translation>取消调平：清除 RST 2 设置的相对俯仰角和横滚角，恢复绝对角度。</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Attitude reset and level</source>
        <translation>姿态复位与调平</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>What to reset</source>
        <translation>复位内容</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Heading reset (ATT RST 1)</source>
        <translation>航向角清零（ATT RST 1）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Relative zero of pitch and roll (ATT RST 2)</source>
        <translation>俯仰角和横滚角相对置零（ATT RST 2）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Auto level (ATT RST 3)</source>
        <translation>自动调平（ATT RST 3）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cancel levelling (ATT RST 5)</source>
        <translation>取消调平（ATT RST 5）</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Hold the module still</source>
        <translation>保持模块静止</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Send</source>
        <translation>发送</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Result</source>
        <translation>结果</translation>
    </message>
    <message>
        <location line="+66"/>
        <source>not still yet (%1 of %2 s)</source>
        <translation>尚未静止（%1 / %2 s）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>not level: pitch %1, roll %2 deg (each must be within %3 deg of level or upside down)</source>
        <translation>未水平：俯仰角 %1，横滚角 %2 deg（均须在水平或倒置位置的 %3 deg 以内）</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Roll %1, pitch %2, yaw %3 deg; gyro spread %4 deg/s.
%5</source>
        <translation>横滚角 %1，俯仰角 %2，航向角 %3 deg；陀螺仪波动 %4 deg/s。
%5</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Ready: send CONFIG ATT RST %1.</source>
        <translation>就绪：发送 CONFIG ATT RST %1。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Waiting: %1.</source>
        <translation>等待中：%1。</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>The device accepted CONFIG ATT RST %1 (OK).</source>
        <translation>设备已接受 CONFIG ATT RST %1（OK）。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The device did not answer CONFIG ATT RST %1: its firmware may not know this variant.</source>
        <translation>设备未应答 CONFIG ATT RST %1：其固件可能不支持此模式。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The device refused CONFIG ATT RST %1 (ERR).</source>
        <translation>设备拒绝了 CONFIG ATT RST %1（ERR）。</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>Nothing was sent.</source>
        <translation>未发送任何指令。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Attitude now: roll %1, pitch %2, yaw %3 deg. Save it with SAVECONFIG if it should survive a restart (RST 2).</source>
        <translation>当前姿态：横滚角 %1，俯仰角 %2，航向角 %3 deg。如需在重启后保留（RST 2），请用 SAVECONFIG 保存。</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::AttitudeWidget</name>
    <message>
        <location filename="../ui/attitude/attitude_widget.cpp" line="+411"/>
        <source>X</source>
        <translation>X</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Y</source>
        <translation>Y</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Z</source>
        <translation>Z</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>N</source>
        <translation>N</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>E (x)</source>
        <translation>E (x)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>N (y)</source>
        <translation>N (y)</translation>
    </message>
    <message>
        <location line="-4"/>
        <location line="+5"/>
        <source>U (z)</source>
        <translation>U (z)</translation>
    </message>
    <message>
        <location line="-116"/>
        <source>ENU 3-1-2</source>
        <translation>ENU 3-1-2</translation>
    </message>
    <message>
        <location line="+109"/>
        <location line="+10"/>
        <source>N (x)</source>
        <translation>N (x)</translation>
    </message>
    <message>
        <location line="-9"/>
        <source>W (y)</source>
        <translation>W (y)</translation>
    </message>
    <message>
        <location line="-110"/>
        <source>NWU 3-1-2</source>
        <translation>NWU 3-1-2</translation>
    </message>
    <message>
        <location line="-15"/>
        <source>%1° in %2 s</source>
        <translation>%2 s 内最大 %1°</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>NWU 3-1-2 (assumed)</source>
        <translation>NWU 3-1-2（假定）</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>ENU 3-1-2 (assumed)</source>
        <translation>ENU 3-1-2（假定）</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>World frame assumed %1: the module&apos;s LOG COMCONFIG reply names no COORD</source>
        <translation>假定世界坐标系为 %1：模块的 LOG COMCONFIG 应答中没有 COORD</translation>
    </message>
    <message>
        <location line="+113"/>
        <source>E (y)</source>
        <translation>E (y)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>D (z)</source>
        <translation>D (z)</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+386"/>
        <source>NED 3-2-1</source>
        <translation>NED 3-2-1</translation>
    </message>
    <message>
        <location line="-386"/>
        <source>NED 3-2-1 (assumed)</source>
        <translation>NED 3-2-1（假定）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>No attitude yet</source>
        <translation>尚无姿态数据</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Roll</source>
        <translation>横滚角</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Pitch</source>
        <translation>俯仰角</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Yaw</source>
        <translation>航向角</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Heading</source>
        <translation>方位角</translation>
    </message>
    <message>
        <location line="-108"/>
        <location line="+1"/>
        <location line="+108"/>
        <location line="+1"/>
        <source>Drag to turn the view, double-click to reset it</source>
        <translation>拖动以旋转视图，双击以复位</translation>
    </message>
    <message>
        <location line="+389"/>
        <source>Show ImuDesk&apos;s reference attitude</source>
        <translation>显示 ImuDesk 的参考姿态</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>ImuDesk&apos;s own filter on the module&apos;s raw gyro and accelerometer, drawn as an outline: started from the module&apos;s heading when it last rested for 1 s</source>
        <translation>ImuDesk 用模块原始陀螺仪和加速度计数据自行解算的姿态，以轮廓线显示：从模块上次静止 1 s 时的航向开始</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Reset view</source>
        <translation>复位视图</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::BandwidthCalculator</name>
    <message>
        <location filename="../ui/charts/bandwidth_calculator.cpp" line="+33"/>
        <source>Baud rate:</source>
        <translation>波特率：</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>HI83 fields (MAP):</source>
        <translation>HI83 字段（MAP）：</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Message</source>
        <translation>数据包</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Rate</source>
        <translation>频率</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Bytes per frame</source>
        <translation>每帧字节数</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Highest usual rate at this baud</source>
        <translation>此波特率下的常用最高频率</translation>
    </message>
    <message>
        <location line="+6"/>
        <source> Hz</source>
        <translation> Hz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>off</source>
        <translation>关闭</translation>
    </message>
    <message>
        <location line="+65"/>
        <source>%1 Hz</source>
        <translation>%1 Hz</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>not even 1 Hz</source>
        <translation>不足 1 Hz</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 of %2 bytes/s (%3 % of the link)</source>
        <translation>%1 / %2 字节/秒（占链路 %3 %）</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::BridgeController</name>
    <message>
        <location filename="../ui/bridge/bridge_controller.cpp" line="+87"/>
        <source>Live bridge %1</source>
        <translation>实时桥接 %1</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>clients: %1</source>
        <translation>客户端：%1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>sent: %1</source>
        <translation>已发送：%1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>dropped: %1</source>
        <translation>已丢弃：%1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Live bridge</source>
        <translation>实时桥接</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>UDP: %1</source>
        <translation>UDP：%1</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::BusConnect</name>
    <message>
        <location filename="../ui/bus/bus_connect_dialog.cpp" line="+27"/>
        <source>Connect</source>
        <translation>连接</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::CalibrationHistoryDialog</name>
    <message>
        <location filename="../ui/calibration/calibration_history_dialog.cpp" line="-199"/>
        <source>Calibration history</source>
        <translation>校准历史</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Devices with calibration runs (by serial number)</source>
        <translation>有校准记录的设备（按序列号）</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Before (raw samples)</source>
        <translation>校准前（原始样本）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>After (corrected by this run)</source>
        <translation>校准后（经本次校准校正）</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Export report (PDF)…</source>
        <translation>导出报告（PDF）…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Export samples (CSV)…</source>
        <translation>导出样本（CSV）…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Open folder</source>
        <translation>打开文件夹</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Delete</source>
        <translation>删除</translation>
    </message>
    <message>
        <location line="+113"/>
        <source>No calibration runs yet. The calibration wizards keep every finished run here, in %1.</source>
        <translation>尚无校准记录。校准向导会将每次完成的校准保存在这里，位于 %1。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Select a run.</source>
        <translation>请选择一条校准记录。</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Verdict: %1</source>
        <translation>结论：%1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1, serial %2, firmware %3, %4 UTC, %5 samples</source>
        <translation>%1，序列号 %2，固件 %3，%4 UTC，%5 个样本</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unknown product</source>
        <translation>未知产品</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+1"/>
        <source>unknown</source>
        <translation>未知</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>The samples could not be read: %1</source>
        <translation>无法读取样本：%1</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>Right: the same samples corrected by this run&apos;s hard and soft iron.</source>
        <translation>右：经本次校准的硬磁和软磁参数校正后的同一组样本。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>This run has no usable correction: both spheres show the raw samples.</source>
        <translation>本次校准没有可用的校正参数：两个球面均显示原始样本。</translation>
    </message>
    <message>
        <location line="+16"/>
        <location line="+16"/>
        <location line="+21"/>
        <source>Select a run first.</source>
        <translation>请先选择一条校准记录。</translation>
    </message>
    <message>
        <location line="-14"/>
        <source>Cannot write %1: %2. Choose another folder.</source>
        <translation>无法写入 %1：%2。请选择其他文件夹。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Cannot write %1: %2. Check the free disk space and try again.</source>
        <translation>无法写入 %1：%2。请检查磁盘剩余空间后重试。</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Cannot delete %1: check the folder&apos;s permissions.</source>
        <translation>无法删除 %1：请检查文件夹权限。</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>Export calibration report</source>
        <translation>导出校准报告</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PDF files (*.pdf)</source>
        <translation>PDF 文件 (*.pdf)</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Export calibration samples</source>
        <translation>导出校准样本</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CSV files (*.csv)</source>
        <translation>CSV 文件 (*.csv)</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Delete calibration run</source>
        <translation>删除校准记录</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Delete the %1 run of %2 and its samples? This cannot be undone.
%3</source>
        <translation>删除 %2 的 %1 校准记录及其样本？此操作无法撤销。
%3</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::CanConfigPanel</name>
    <message>
        <location filename="../ui/bus/can_config_panel.cpp" line="+32"/>
        <location line="+2"/>
        <location line="+1"/>
        <location line="+1"/>
        <location line="+3"/>
        <location line="+1"/>
        <source>Apply</source>
        <translation>应用</translation>
    </message>
    <message>
        <location line="-8"/>
        <source>SYNC mode (TPDO sent on each SYNC)</source>
        <translation>SYNC 模式（每收到一次 SYNC 发送一次 TPDO）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Send SYNC</source>
        <translation>发送 SYNC</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Output on</source>
        <translation>开启输出</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Output off</source>
        <translation>关闭输出</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Save</source>
        <translation>保存</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Reset</source>
        <translation>复位</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Factory defaults…</source>
        <translation>恢复出厂设置…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Scan nodes 1–127</source>
        <translation>扫描节点 1–127</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+3"/>
        <location line="+3"/>
        <source> ms</source>
        <translation> ms</translation>
    </message>
    <message>
        <location line="-2"/>
        <source>periodic SYNC off</source>
        <translation>不周期发送 SYNC</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Angles, acc., rate (0x02)</source>
        <translation>角度、加速度、角速度（0x02）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>HEC495 work mode, object 0x6245: 0x02 pitch, roll, acceleration and rate (default); 0x0A rate at 500 Hz</source>
        <translation>HEC495 工作模式，对象 0x6245：0x02 输出俯仰、横滚、加速度和角速度（默认）；0x0A 以 500 Hz 输出角速度</translation>
    </message>
    <message>
        <location line="+219"/>
        <source>%1 kbit/s</source>
        <translation>%1 kbit/s</translation>
    </message>
    <message>
        <location line="-228"/>
        <source>Heading reset (J1939 1)</source>
        <translation>航向角复位（J1939 1）</translation>
    </message>
    <message>
        <location line="-18"/>
        <source>Trigger once</source>
        <translation>触发一次</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>X reversed</source>
        <translation>X 反向</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Y reversed</source>
        <translation>Y 反向</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>All nodes on</source>
        <translation>所有节点开</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>All nodes off</source>
        <translation>所有节点关</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Set relative zero (2)</source>
        <translation>设置相对零位（2）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Auto level (J1939 3)</source>
        <translation>自动调平（J1939 3）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Clear zero (5)</source>
        <translation>清除零位（5）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>J1939 register 0x96: the module sends the chosen PGN once (no reply; the frame is the answer)</source>
        <translation>J1939 寄存器 0x96：模块发送一次所选 PGN（无应答；数据帧即为回应）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Inclinometer X axis direction: J1939 register 0x9E, CANopen object 0x209E (0 default, 1 reversed)</source>
        <translation>倾角仪 X 轴正负方向：J1939 寄存器 0x9E，CANopen 对象 0x209E（0 默认，1 反向）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Inclinometer Y axis direction: J1939 register 0x9F, CANopen object 0x209F (0 default, 1 reversed)</source>
        <translation>倾角仪 Y 轴正负方向：J1939 寄存器 0x9F，CANopen 对象 0x209F（0 默认，1 反向）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Rate at 500 Hz (0x0A)</source>
        <translation>500 Hz 角速度（0x0A）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>HEC495 PDO mode, object 0x1080</source>
        <translation>HEC495 PDO 模式，对象 0x1080</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>NMT start to node 0: every node on the bus starts its PDOs (HEC495: not saved)</source>
        <translation>向节点 0 发送 NMT 启动：总线上所有节点开始发送 PDO（HEC495：不保存）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>NMT stop to node 0: every node on the bus stops its PDOs (HEC495: not saved)</source>
        <translation>向节点 0 发送 NMT 停止：总线上所有节点停止发送 PDO（HEC495：不保存）</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Protocol:</source>
        <translation>协议：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Output period:</source>
        <translation>输出周期：</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>SYNC:</source>
        <translation>SYNC：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Heartbeat:</source>
        <translation>心跳：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Node ID:</source>
        <translation>节点 ID：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CAN bit rate:</source>
        <translation>CAN 波特率：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Attitude:</source>
        <translation>姿态：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Inclinometer:</source>
        <translation>倾角仪：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>HEC495 PDO:</source>
        <translation>HEC495 PDO：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Work mode:</source>
        <translation>工作模式：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Output:</source>
        <translation>输出：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Every node:</source>
        <translation>所有节点：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Settings:</source>
        <translation>设置：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Discovery:</source>
        <translation>节点发现：</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Settings</source>
        <translation>设置</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Actions</source>
        <translation>操作</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>SYNC mode on</source>
        <translation>开启 SYNC 模式</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>SYNC mode off</source>
        <translation>关闭 SYNC 模式</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>heartbeat</source>
        <translation>心跳</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>node ID %1</source>
        <translation>节点 ID %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>bit rate</source>
        <translation>波特率</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>output on</source>
        <translation>开启输出</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>output off</source>
        <translation>关闭输出</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>trigger %1 once</source>
        <translation>触发一次 %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>inclinometer X reversed</source>
        <translation>倾角仪 X 反向</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>inclinometer X default</source>
        <translation>倾角仪 X 默认</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>inclinometer Y reversed</source>
        <translation>倾角仪 Y 反向</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>inclinometer Y default</source>
        <translation>倾角仪 Y 默认</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>every node on</source>
        <translation>所有节点开</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>every node off</source>
        <translation>所有节点关</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>save</source>
        <translation>保存</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>reset</source>
        <translation>复位</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Factory defaults</source>
        <translation>恢复出厂设置</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Restore the module&apos;s default user settings? It saves and resets itself.</source>
        <translation>恢复模块的默认用户设置？模块会自动保存并复位。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>factory defaults</source>
        <translation>恢复出厂设置</translation>
    </message>
    <message>
        <location line="+46"/>
        <source>Scan cancelled; nodes answering so far: %1</source>
        <translation>扫描已取消；目前有应答的节点：%1</translation>
    </message>
    <message>
        <location line="+0"/>
        <location line="+1"/>
        <source>none</source>
        <translation>无</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Scan finished; nodes answering SDO: %1</source>
        <translation>扫描完成；应答 SDO 的节点：%1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Node %1 (%2, %3)</source>
        <translation>节点 %1（%2，%3）</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>no session</source>
        <translation>无会话</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>detecting…</source>
        <translation>正在检测…</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>TPDO%1 (%2)</source>
        <translation>TPDO%1（%2）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>PDO %1 Hz</source>
        <translation>PDO %1 Hz</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>PDO off</source>
        <translation>PDO 关闭</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>X message only (0)</source>
        <translation>仅 X 报文（0）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>X and Y messages (1)</source>
        <translation>X 和 Y 报文（1）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Float (0)</source>
        <translation>浮点（0）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Fixed point (1)</source>
        <translation>定点（1）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Float, 0x180/0x280 only (3)</source>
        <translation>浮点，仅 0x180/0x280（3）</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>%1 every %2 ms</source>
        <translation>%1，每 %2 ms</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>→ %1 …</source>
        <translation>→ %1 …</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>✓ %1: confirmed (%2)</source>
        <translation>✓ %1：已确认（%2）</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>✗ %1</source>
        <translation>✗ %1</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::CanConnectDialog</name>
    <message>
        <location filename="../ui/bus/bus_connect_dialog.cpp" line="+99"/>
        <source>Connect over CAN</source>
        <translation>通过 CAN 连接</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The Qt CAN plugin of the adapter: socketcan for Linux CAN interfaces, peakcan for PEAK adapters, virtualcan for a bus inside this computer</source>
        <translation>适配器对应的 Qt CAN 插件：Linux CAN 接口用 socketcan，PEAK 适配器用 peakcan，本机内部的虚拟总线用 virtualcan</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>P&amp;lugin:</source>
        <translation>插件(&amp;L)：</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The interface of the plugin, e.g. can0</source>
        <translation>插件的接口名称，例如 can0</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Interface:</source>
        <translation>接口(&amp;I)：</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Bit rate of the bus: the rates the chosen device&apos;s manual lists, its factory rate chosen first (HiPNUC 500 kbit/s, HEC495 250 kbit/s)</source>
        <translation>总线波特率：所选设备手册列出的速率，默认选中其出厂速率（HiPNUC 500 kbit/s，HEC495 250 kbit/s）</translation>
    </message>
    <message>
        <location line="+81"/>
        <source>Keep the interface&apos;s setting</source>
        <translation>保持接口现有设置</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 kbit/s (factory)</source>
        <translation>%1 kbit/s（出厂）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 kbit/s</source>
        <translation>%1 kbit/s</translation>
    </message>
    <message>
        <location line="-83"/>
        <source>&amp;Bit rate:</source>
        <translation>波特率(&amp;B)：</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>CAN FD</source>
        <translation>CAN FD</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>A CAN FD bus: needed for the J1939 FF5A frame (64 bytes); the module must have CAN FD output enabled, which its manual gives no command for</source>
        <translation>CAN FD 总线：接收 J1939 FF5A 帧（64 字节）所需；模块必须已启用 CAN FD 输出，手册未给出相应命令</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 Mbit/s</source>
        <translation>%1 Mbit/s</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Bit rate of the CAN FD data phase (the manual: usually 4 Mbit/s)</source>
        <translation>CAN FD 数据段波特率（手册：通常为 4 Mbit/s）</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>&amp;Data phase:</source>
        <translation>数据段(&amp;D)：</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Detect from the traffic</source>
        <translation>根据总线报文自动检测</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>HEC495 compass</source>
        <translation>HEC495 罗盘</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>P&amp;rotocol:</source>
        <translation>协议(&amp;R)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Extended frames (0x18FA…)</source>
        <translation>扩展帧（0x18FA…）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The HEC495&apos;s extended-frame variant: requests on 0x18FA0227, replies on 0x18FA0216, data on 0x18FA0316 and 0x18FA0416 (its manual, &quot;CAN 扩展帧命令格式&quot;)</source>
        <translation>HEC495 的扩展帧方式：请求 0x18FA0227，应答 0x18FA0216，数据 0x18FA0316 和 0x18FA0416（其手册“CAN 扩展帧命令格式”）</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>First that sends</source>
        <translation>最先发送的节点</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The node ID (CANopen) or source address (J1939) to follow</source>
        <translation>要跟随的节点 ID（CANopen）或源地址（J1939）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Node:</source>
        <translation>节点(&amp;N)：</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>1.7.x (node-ID object 0x209C)</source>
        <translation>1.7.x（节点 ID 对象 0x209C）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>1.6.6 (node-ID object 0x20A0)</source>
        <translation>1.6.6（节点 ID 对象 0x20A0）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>HiPNUC CANopen firmware: where it keeps its node ID</source>
        <translation>HiPNUC CANopen 固件：节点 ID 的存放位置</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Firmware:</source>
        <translation>固件(&amp;F)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Start a simulated device on this bus</source>
        <translation>在此总线上启动模拟设备</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A simulated module of the chosen protocol answers on the bus (use the virtualcan plugin to try it without hardware)</source>
        <translation>所选协议的模拟模块会在总线上应答（无硬件时可用 virtualcan 插件试用）</translation>
    </message>
    <message>
        <location line="+47"/>
        <source>The module can be switched to %1 kbit/s (register 0x9A, after save and reset).</source>
        <translation>模块可切换到 %1 kbit/s（寄存器 0x9A，保存并复位后生效）。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The module can be switched to %1 kbit/s (object 0x209A, after save and reset; no 800 kbit/s in CANopen).</source>
        <translation>模块可切换到 %1 kbit/s（对象 0x209A，保存并复位后生效；CANopen 没有 800 kbit/s）。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The compass can be switched to %1 kbit/s (object 0x1020, after a power cycle).</source>
        <translation>罗盘可切换到 %1 kbit/s（对象 0x1020，重新上电后生效）。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Choose the protocol to see the rates its devices use.</source>
        <translation>选择协议以查看其设备使用的速率。</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::CanMonitorWidget</name>
    <message>
        <location filename="../ui/bus/can_monitor_widget.cpp" line="+21"/>
        <source>Clear</source>
        <translation>清空</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Export CSV…</source>
        <translation>导出 CSV…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Extended</source>
        <translation>扩展帧</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>FD</source>
        <translation>FD</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Send</source>
        <translation>发送</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Filter: ID or meaning</source>
        <translation>过滤：ID 或含义</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Pause</source>
        <translation>暂停</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>ID (hex)</source>
        <translation>ID（十六进制）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>data (hex bytes)</source>
        <translation>数据（十六进制字节）</translation>
    </message>
    <message>
        <location line="+43"/>
        <source>%1 frames, %2 IDs</source>
        <translation>%1 帧，%2 个 ID</translation>
    </message>
    <message>
        <location line="+2"/>
        <source> — paused (%1 frames not shown)</source>
        <translation> — 已暂停（%1 帧未显示）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source> — %1 frames of IDs beyond the %2-row limit</source>
        <translation> — 另有 %1 帧属于超出 %2 行上限的 ID</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>The ID must be hexadecimal, 0 to 1FFFFFFF.</source>
        <translation>ID 必须为十六进制数，范围 0 至 1FFFFFFF。</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>The ID must be hexadecimal, 0 to 7FF (tick Extended for 29-bit IDs).</source>
        <translation>ID 必须为十六进制数，范围 0 至 7FF（29 位 ID 请勾选“扩展帧”）。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The data must be pairs of hexadecimal digits, e.g. 2B 00 18 05 0A 00 00 00.</source>
        <translation>数据必须为成对的十六进制数字，例如 2B 00 18 05 0A 00 00 00。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>A CAN FD frame carries at most 64 bytes.</source>
        <translation>CAN FD 帧最多携带 64 字节。</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>A classic CAN frame carries at most 8 bytes (tick FD for more).</source>
        <translation>经典 CAN 帧最多携带 8 字节（需要更多请勾选 FD）。</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Saved %1 IDs to %2</source>
        <translation>已将 %1 个 ID 保存到 %2</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Export CAN frames</source>
        <translation>导出 CAN 帧</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>CSV files (*.csv)</source>
        <translation>CSV 文件 (*.csv)</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::CanSettingsTable</name>
    <message>
        <location filename="../ui/bus/can_settings_table.cpp" line="+57"/>
        <source>Setting</source>
        <translation>设置项</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>On the module</source>
        <translation>模块中的值</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>New value</source>
        <translation>新值</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Read back</source>
        <translation>读回</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Read from module</source>
        <translation>从模块读取(&amp;R)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Read every setting the module can report (J1939 register reads, CANopen SDO uploads)</source>
        <translation>读取模块能报告的所有设置（J1939 寄存器读取、CANopen SDO 上传）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Write changed</source>
        <translation>写入已更改项(&amp;W)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Write the new values you changed; each is read back and marked verified or not</source>
        <translation>写入已更改的新值；每项都会读回并标记是否已校验</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The value on the module is read before anything is written; a write is read back.</source>
        <translation>写入前先读取模块中的值；写入后会读回校验。</translation>
    </message>
    <message>
        <location line="+65"/>
        <source>not readable</source>
        <translation>无法读取</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>%1; %2</source>
        <translation>%1；%2</translation>
    </message>
    <message>
        <location line="+85"/>
        <source>reading…</source>
        <translation>正在读取…</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>writing…</source>
        <translation>正在写入…</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>verified</source>
        <translation>已校验</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>confirmed by its reply (cannot be read back)</source>
        <translation>已由应答确认（无法读回）</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>not taken: the module holds %1</source>
        <translation>未生效：模块中的值为 %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>not confirmed: %1</source>
        <translation>未确认：%1</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>could not be read: %1</source>
        <translation>无法读取：%1</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::ChartPanel</name>
    <message>
        <location filename="../ui/charts/chart_panel.cpp" line="+146"/>
        <source>Charts</source>
        <translation>图表</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Choose the charts to show; they share the area</source>
        <translation>选择要显示的图表；它们共享绘图区域</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Window:</source>
        <translation>时间窗(&amp;W)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Time span shown by every chart</source>
        <translation>每个图表显示的时间跨度</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Run</source>
        <translation>运行</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Pause</source>
        <translation>暂停</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Follow the newest data again (Pause key)</source>
        <translation>重新跟随最新数据（Pause 键）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Freeze every chart; the data keeps being recorded (Pause key)</source>
        <translation>冻结所有图表；数据仍在继续记录（Pause 键）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Time axis:</source>
        <translation>时间轴(&amp;T)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Device clock</source>
        <translation>设备时钟</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Common time</source>
        <translation>公共时间</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Device clock: the module&apos;s own timestamps, where lost samples show as gaps. Common time: when each sample was taken, on this computer&apos;s clock (from the device&apos;s own clock where it has one, else when it arrived): every device on one time base.</source>
        <translation>设备时钟：模块自身的时间戳，丢失的样本显示为空缺。公共时间：每个样本的采样时刻，以本机时钟表示（设备有自身时钟时据此换算，否则取样本的到达时间）：所有设备使用同一时间基准。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Cursor</source>
        <translation>游标</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A crosshair that follows the mouse and reads out every chart at the same time</source>
        <translation>跟随鼠标的十字线，同时读出每个图表的数值</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save all as PNG…</source>
        <translation>全部保存为 PNG…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save the charts shown as one PNG image</source>
        <translation>将显示的图表保存为一张 PNG 图片</translation>
    </message>
    <message>
        <location line="+40"/>
        <source>This device&apos;s output carries no acceleration at its current setting.</source>
        <translation>该设备当前设置下的输出不含加速度。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>This device&apos;s output carries no angular rate at its current setting.</source>
        <translation>该设备当前设置下的输出不含角速度。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>This device&apos;s output carries no magnetic field at its current setting.</source>
        <translation>该设备当前设置下的输出不含磁场。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>This device&apos;s output carries no Euler angles at its current setting.</source>
        <translation>该设备当前设置下的输出不含欧拉角。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>This device&apos;s output carries no quaternion at its current setting.</source>
        <translation>该设备当前设置下的输出不含四元数。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>This device&apos;s output carries no pressure at its current setting.</source>
        <translation>该设备当前设置下的输出不含气压。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>This device&apos;s output carries no temperature at its current setting.</source>
        <translation>该设备当前设置下的输出不含温度。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>This device&apos;s output carries no relative magnetic field at its current setting.</source>
        <translation>该设备当前设置下的输出不含相对磁场。</translation>
    </message>
    <message numerus="yes">
        <location line="+210"/>
        <source>%n chart(s) saved as one PNG in %1 (%2)</source>
        <translation>
            <numerusform>已将 %n 个图表保存为一张 PNG，位于 %1（%2）</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>imudesk::ui::ChartView</name>
    <message>
        <location filename="../ui/charts/chart_view.cpp" line="+91"/>
        <source>Accelerometer</source>
        <translation>加速度计</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Gyroscope</source>
        <translation>陀螺仪</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Magnetometer</source>
        <translation>磁力计</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Euler angles</source>
        <translation>欧拉角</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Quaternion</source>
        <translation>四元数</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Air pressure</source>
        <translation>气压</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+15"/>
        <source>Temperature</source>
        <translation>温度</translation>
    </message>
    <message>
        <location line="-14"/>
        <source>Relative magnetic field</source>
        <translation>相对磁场</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Acceleration</source>
        <translation>加速度</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Angular velocity</source>
        <translation>角速度</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Magnetic field</source>
        <translation>磁场</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Angle</source>
        <translation>角度</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Quaternion component</source>
        <translation>四元数分量</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Pressure</source>
        <translation>气压</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Magnetic field (north = 1)</source>
        <translation>磁场（北向 = 1）</translation>
    </message>
    <message>
        <location line="+8"/>
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
        <location line="+2"/>
        <source>Pa</source>
        <translation>Pa</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>°C</source>
        <translation>°C</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>Device time (s)</source>
        <translation>设备时间（s）</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 min</source>
        <translation>%1 min</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>the chart could not be drawn</source>
        <translation>无法绘制图表</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Could not save the chart as %1: %2</source>
        <translation>无法将图表保存为 %1：%2</translation>
    </message>
    <message>
        <location line="+123"/>
        <source>%1 (%2)</source>
        <comment>quantity (unit)</comment>
        <translation>%1（%2）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Click an axis in the legend to hide or show it; right-click for the vertical range and to save this chart</source>
        <translation>单击图例中的轴可隐藏或显示该轴；右键单击可设置纵轴范围并保存此图表</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Right-click for the vertical range and to save this chart</source>
        <translation>右键单击可设置纵轴范围并保存此图表</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Fit the vertical axis to the data shown; off: use the fixed range</source>
        <translation>纵轴自动适应显示的数据；关闭时使用固定范围</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Fixed range:</source>
        <translation>固定范围：</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Fixed range (%1):</source>
        <translation>固定范围（%1）：</translation>
    </message>
    <message>
        <location line="-2"/>
        <source>Auto scale</source>
        <translation>自动缩放</translation>
    </message>
    <message>
        <location line="-171"/>
        <source>Common time (s)</source>
        <translation>公共时间（s）</translation>
    </message>
    <message>
        <location line="+175"/>
        <source>Lower end of the vertical axis (no unit)</source>
        <translation>纵轴下限（无单位）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Upper end of the vertical axis (no unit)</source>
        <translation>纵轴上限（无单位）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Lower end of the vertical axis, in %1</source>
        <translation>纵轴下限，单位 %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Upper end of the vertical axis, in %1</source>
        <translation>纵轴上限，单位 %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Save as PNG…</source>
        <translation>另存为 PNG…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save this chart as a PNG image</source>
        <translation>将此图表保存为 PNG 图像</translation>
    </message>
    <message>
        <location line="+186"/>
        <source>m/s²</source>
        <translation>m/s²</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>rad/s</source>
        <translation>rad/s</translation>
    </message>
    <message>
        <location line="+181"/>
        <source>t = %1 s</source>
        <translation>t = %1 s</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>%1 %2 %3</source>
        <comment>crosshair read-out: axis, value, unit</comment>
        <translation>%1 %2 %3</translation>
    </message>
    <message>
        <location line="+23"/>
        <location line="+7"/>
        <source>Save Chart as PNG</source>
        <translation>将图表保存为 PNG</translation>
    </message>
    <message>
        <location line="-7"/>
        <source>PNG images (*.png)</source>
        <translation>PNG 图像 (*.png)</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::CommandLogWidget</name>
    <message>
        <location filename="../ui/workspace/command_log_widget.cpp" line="+170"/>
        <source>Copy</source>
        <translation>复制</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Copy the selected commands as tab-separated text</source>
        <translation>将所选指令复制为制表符分隔的文本</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Copy all</source>
        <translation>全部复制</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Copy every command as tab-separated text</source>
        <translation>将所有指令复制为制表符分隔的文本</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Clear</source>
        <translation>清空</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Remove every command from the list</source>
        <translation>从列表中移除所有指令</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::ComparisonChart</name>
    <message>
        <location filename="../ui/charts/comparison_chart.cpp" line="+110"/>
        <source>&amp;Channel:</source>
        <translation>通道(&amp;C)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The quantity compared across the devices</source>
        <translation>在各设备之间对比的物理量</translation>
    </message>
    <message>
        <location line="+5"/>
        <location line="+16"/>
        <source>%1 (%2)</source>
        <comment>quantity (unit)</comment>
        <translation>%1（%2）</translation>
    </message>
    <message>
        <location line="-14"/>
        <source>&amp;Window:</source>
        <translation>时间窗(&amp;W)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Time span shown</source>
        <translation>显示的时间跨度</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Save as PNG…</source>
        <translation>另存为 PNG…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save this chart as a PNG image</source>
        <translation>将此图表保存为 PNG 图像</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Resume</source>
        <translation>继续</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Pause</source>
        <translation>暂停</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Follow the newest data again</source>
        <translation>重新跟随最新数据</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Freeze this chart; the data keeps being recorded</source>
        <translation>冻结此图表；数据仍会继续记录</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::CompassPoseView</name>
    <message>
        <location filename="../ui/attitude/compass_pose_view.cpp" line="+69"/>
        <source>N</source>
        <translation>北</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>E</source>
        <translation>东</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>S</source>
        <translation>南</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>W</source>
        <translation>西</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>R%1</source>
        <translation>R%1</translation>
    </message>
    <message numerus="yes">
        <location line="+12"/>
        <source>%n point(s)</source>
        <translation>
            <numerusform>%n 个点</numerusform>
        </translation>
    </message>
    <message>
        <location line="+17"/>
        <source>No attitude received yet</source>
        <translation>尚未收到姿态数据</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Heading %1°  pitch %2°  roll %3°</source>
        <translation>航向角 %1°  俯仰角 %2°  横滚角 %3°</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::ConfigPanel</name>
    <message>
        <location filename="../ui/configuration/config_panel.cpp" line="+177"/>
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>%1=%2: %3 %4</source>
        <translation>%1=%2：%3 %4</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1 done</source>
        <translation>%1 完成</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1 failed: %2</source>
        <translation>%1 失败：%2</translation>
    </message>
    <message>
        <location line="+40"/>
        <source>Read all</source>
        <translation>全部读取</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Apply</source>
        <translation>应用</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save to flash</source>
        <translation>保存到闪存</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Reboot</source>
        <translation>重启</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Factory reset…</source>
        <translation>恢复出厂设置…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Mounting…</source>
        <translation>安装方式…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Copy as command line</source>
        <translation>复制为命令行</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>absolute</source>
        <translation>绝对</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>relative</source>
        <translation>相对</translation>
    </message>
    <message>
        <location line="+2"/>
        <source> deg</source>
        <translation> deg</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1, firmware %2, serial %3 (%4)</source>
        <translation>%1，固件 %2，序列号 %3（%4）</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Not read yet: press Read all.</source>
        <translation>尚未读取：请点击“全部读取”。</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>! %1</source>
        <translation>! %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>No pending changes.</source>
        <translation>没有待应用的更改。</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Link: %1 of %2 bytes/s (%3 %) at %4 baud</source>
        <translation>链路：%1 / %2 字节/秒（%3 %），波特率 %4</translation>
    </message>
    <message>
        <location line="+39"/>
        <source>✗ %1</source>
        <translation>✗ %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>? %1</source>
        <translation>? %1</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Output too fast for the link</source>
        <translation>输出速率超出链路能力</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Apply anyway?</source>
        <translation>仍要应用吗？</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Factory reset</source>
        <translation>恢复出厂设置</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Go ahead?</source>
        <translation>是否继续？</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::ConnectionBar</name>
    <message>
        <location filename="../ui/workspace/connection_bar.cpp" line="+190"/>
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
        <location line="+40"/>
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
        <source>Find devices…</source>
        <translation>查找设备…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Sweep every serial port and CAN bus for devices (Ctrl+Shift+F)</source>
        <translation>扫描所有串口和 CAN 总线上的设备（Ctrl+Shift+F）</translation>
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
        <source>Auto finds the device and the baud rate it talks at, starting with 115200</source>
        <translation>自动：找出设备及其使用的波特率，从 115200 开始</translation>
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
        <location line="+12"/>
        <source>Simulated %1</source>
        <translation>模拟 %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Simulated %1 (firmware %2)</source>
        <translation>模拟 %1（固件 %2）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 (%2)</source>
        <translation>%1（%2）</translation>
    </message>
    <message>
        <location line="+33"/>
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
        <location filename="../ui/workspace/console_widget.cpp" line="+88"/>
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
        <source>Invalid reply: %1</source>
        <translation>无效应答：%1</translation>
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
        <translation>输入 ASCII 指令（例如 LOG VERSION）后按回车</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Enter sends the command; Up and Down recall earlier commands</source>
        <translation>回车发送指令；上、下方向键调出历史指令</translation>
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
    <name>imudesk::ui::CorrelationPlot</name>
    <message>
        <location filename="../ui/recording/twist_align_dialog.cpp" line="+168"/>
        <source>Normalised cross-correlation of each device&apos;s gyro magnitude with the reference&apos;s, against the shift of its time (ms). The marker is the offset found; a good match peaks close to 1.</source>
        <translation>各设备陀螺仪角速度模值与参考设备的归一化互相关，随该设备时间平移量（ms）的变化曲线。标记处为求得的偏移；匹配良好时峰值接近 1。</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>Find offsets to see how each device&apos;s gyro magnitude matches the reference&apos;s.</source>
        <translation>按“计算偏移”后，可在此查看各设备的陀螺仪角速度模值与参考设备的匹配情况。</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>Correlation</source>
        <translation>相关系数</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Shift of the device&apos;s time (ms)</source>
        <translation>设备时间平移（ms）</translation>
    </message>
    <message>
        <location line="+51"/>
        <source>least correlation accepted</source>
        <translation>可接受的最低相关系数</translation>
    </message>
    <message>
        <location line="+41"/>
        <source>%1: %2 ms, correlation %3</source>
        <translation>%1：%2 ms，相关系数 %3</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1: not aligned</source>
        <translation>%1：未对齐</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::DeviceWorkspace</name>
    <message>
        <location filename="../ui/workspace/device_workspace.cpp" line="+365"/>
        <source>New connection</source>
        <translation>新连接</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 on %2</source>
        <translation>%2 上的 %1</translation>
    </message>
    <message>
        <location line="+124"/>
        <source>Reference %1° apart (±%2°)</source>
        <translation>参考姿态相差 %1°（±%2°）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Reference: hold the module still for 1 s to start it</source>
        <translation>参考姿态：让模块静止 1 s 以启动</translation>
    </message>
    <message>
        <location line="+108"/>
        <source>Frames arrive again on %1.</source>
        <translation>%1 上又收到帧了。</translation>
    </message>
    <message>
        <location line="+18"/>
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
        <location line="+2"/>
        <source>Disconnected from %1 — waiting for the device to come back</source>
        <translation>已与 %1 断开，正在等待设备重新连接</translation>
    </message>
    <message>
        <location line="+2"/>
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
        <location line="+2"/>
        <source>world frame %1 assumed</source>
        <translation>假定世界坐标系 %1</translation>
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
        <location line="+2"/>
        <source>The module&apos;s LOG COMCONFIG reply names no COORD: its attitude is drawn as %1, the default, which it did not confirm (CONFIG IMU COORD sets it)</source>
        <translation>模块的 LOG COMCONFIG 应答中没有 COORD：其姿态按默认的 %1 显示，但模块并未确认（可用 CONFIG IMU COORD 设置）</translation>
    </message>
    <message>
        <location line="+10"/>
        <location line="+9"/>
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
        <location line="+13"/>
        <source>CRC errors %1</source>
        <translation>CRC 错误 %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>lost %1</source>
        <translation>丢失 %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>skipped %1 B</source>
        <translation>跳过 %1 B</translation>
    </message>
    <message>
        <location line="+5"/>
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
        <location line="+55"/>
        <source>Console</source>
        <translation>控制台</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Raw bytes</source>
        <translation>原始字节</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Command log</source>
        <translation>指令日志</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Values</source>
        <translation>数值</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Details</source>
        <translation>详情</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>3D attitude</source>
        <translation>3D 姿态</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Time sync</source>
        <translation>时间同步</translation>
    </message>
    <message>
        <location filename="../ui/workspace/device_workspace_layout.cpp" line="+168"/>
        <source>&amp;Monitor</source>
        <translation>监视(&amp;M)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>C&amp;onfigure</source>
        <translation>配置(&amp;O)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>C&amp;alibrate</source>
        <translation>校准(&amp;A)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A&amp;nalyse</source>
        <translation>分析(&amp;N)</translation>
    </message>
    <message>
        <location line="+165"/>
        <source>%1 was floating off the screen</source>
        <translation>%1 浮动在屏幕之外</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 is not used by this link</source>
        <translation>此连接不使用 %1</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>the charts were squeezed</source>
        <translation>图表被挤压</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the 3D attitude view was squeezed</source>
        <translation>3D 姿态视图被挤压</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the values table was squeezed</source>
        <translation>数值表被挤压</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>the values table was too narrow for its columns</source>
        <translation>数值表太窄，无法容纳其各列</translation>
    </message>
    <message>
        <location filename="../ui/workspace/device_workspace.cpp" line="-2"/>
        <source>Configuration</source>
        <translation>配置</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Recording</source>
        <translation>记录</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::ExportDialog</name>
    <message>
        <location filename="../ui/recording/export_dialog.cpp" line="+130"/>
        <source>Export %1</source>
        <translation>导出 %1</translation>
    </message>
    <message>
        <location line="-98"/>
        <source>The capture to export: a recording, a vendor CSV or a raw byte dump; or a recorded session&apos;s folder (or its session.json): every device, aligned in one file</source>
        <translation>要导出的捕获：录制文件、厂商 CSV 或原始字节转储；或已录制会话的文件夹（或其 session.json）：所有设备对齐写入一个文件</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Choose…</source>
        <translation>选择…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Export another capture</source>
        <translation>导出另一个捕获</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Vendor CSV (the vendor tool&apos;s layout; a file per frame type when there are several)</source>
        <translation>厂商 CSV（厂商工具的格式；有多种帧类型时每种一个文件）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Tidy CSV (pandas, PlotJuggler)</source>
        <translation>整洁 CSV（适用于 pandas、PlotJuggler）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>JSON Lines</source>
        <translation>JSON 行格式（JSONL）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>MCAP (ROS 2: PlotJuggler, Foxglove, Lichtblick)</source>
        <translation>MCAP（ROS 2：PlotJuggler、Foxglove、Lichtblick）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>MATLAB .mat (a struct per device, SI units)</source>
        <translation>MATLAB .mat（每台设备一个结构体，国际单位制）</translation>
    </message>
    <message>
        <location line="+7"/>
        <location line="+5"/>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>end</source>
        <translation>结尾</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Export</source>
        <translation>导出</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Show in folder</source>
        <translation>在文件夹中显示</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Open the folder of the written file in the file manager</source>
        <translation>在文件管理器中打开所写文件的文件夹</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Capture:</source>
        <translation>捕获：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Format:</source>
        <translation>格式：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Output:</source>
        <translation>输出：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>From:</source>
        <translation>起始：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>To:</source>
        <translation>结束：</translation>
    </message>
    <message>
        <location line="+46"/>
        <source>Export the session %1</source>
        <translation>导出会话 %1</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>A recorded session is exported whole, every device aligned on the session&apos;s time base</source>
        <translation>已录制的会话整体导出，所有设备按会话的时间基准对齐</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Export capture</source>
        <translation>导出捕获</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Captures, sessions, vendor CSV and raw dumps (*.imucap session.json *.csv *.bin *.raw *.log *.dat *.txt);;All files (*)</source>
        <translation>捕获、会话、厂商 CSV 和原始转储 (*.imucap session.json *.csv *.bin *.raw *.log *.dat *.txt);;所有文件 (*)</translation>
    </message>
    <message>
        <location line="+45"/>
        <source>Exporting…</source>
        <translation>正在导出…</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <location line="+57"/>
        <source>Export cancelled; the partial files were removed.</source>
        <translation>导出已取消；不完整的文件已删除。</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Close</source>
        <translation>关闭</translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>%n row(s) written to %1</source>
        <translation>
            <numerusform>已向 %1 写入 %n 行</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>imudesk::ui::FindDevicesDialog</name>
    <message numerus="yes">
        <location filename="../ui/discovery/find_devices_dialog.cpp" line="+142"/>
        <source>%n device(s) opened, each in a tab of its own.</source>
        <translation>
            <numerusform>已打开 %n 台设备，每台在单独的标签页中。</numerusform>
        </translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Find devices</source>
        <translation>查找设备</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>One sweep of every serial port and CAN bus: each serial family at its rates, silent ports as Modbus RTU lines, CAN buses listened to before anything is sent. Nothing is written to a device and every port is closed afterwards.</source>
        <translation>一次扫描所有串口和 CAN 总线：按各串口设备系列的波特率逐一尝试，无应答的端口作为 Modbus RTU 线路询问，CAN 总线先监听再发送。不会向设备写入任何内容，结束后关闭所有端口。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>More &amp;serial ports:</source>
        <translation>更多串口(&amp;S)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>beside the machine&apos;s, comma-separated, e.g. /dev/pts/3,/dev/ttyUSB4</source>
        <translation>本机串口之外的端口，用逗号分隔，例如 /dev/pts/3,/dev/ttyUSB4</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ports the machine does not list, such as pseudo-terminals</source>
        <translation>本机未列出的端口，例如伪终端</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;CAN buses:</source>
        <translation>CAN 总线(&amp;C)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PLUGIN:INTERFACE, comma-separated, e.g. socketcan:can1,virtualcan:can0</source>
        <translation>插件:接口，用逗号分隔，例如 socketcan:can1,virtualcan:can0</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Every socketcan interface is swept anyway; name the others here</source>
        <translation>所有 socketcan 接口都会被扫描；其他接口请在此填写</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Only these</source>
        <translation>仅扫描这些(&amp;O)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Sweep only the ports and buses named above, not every serial port and socketcan interface of the machine</source>
        <translation>只扫描上面列出的端口和总线，不扫描本机所有串口和 socketcan 接口</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Ask silent ports as &amp;Modbus lines</source>
        <translation>将无应答端口作为 &amp;Modbus 线路询问</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ids 80 and 1 at every rate first, then ids 1-247 at each rate, fastest first, until a device answers or the time is up</source>
        <translation>先在每个波特率下询问 ID 80 和 1，再从最快的波特率开始逐个询问 ID 1-247，直到有设备应答或时间用完</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Time limit:</source>
        <translation>时间上限(&amp;T)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The whole sweep at most, in seconds</source>
        <translation>整个扫描的最长时间，单位为秒</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Simulated &amp;bench</source>
        <translation>模拟测试台(&amp;B)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Start simulated devices to find: a HiPNUC module at 460800 baud, an HEC495 at 4800 baud address 7, a Modbus module at 38400 baud id 17, a silent port, and on virtualcan can1 a J1939 module and two CANopen modules sharing node 5</source>
        <translation>启动供查找的模拟设备：一个波特率 460800 的 HiPNUC 模块，一个波特率 4800、地址 7 的 HEC495，一个波特率 38400、ID 17 的 Modbus 模块，一个无应答端口，以及 virtualcan can1 上的一个 J1939 模块和两个共用节点 5 的 CANopen 模块</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Sweep</source>
        <translation>扫描(&amp;S)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Start the sweep (F5)</source>
        <translation>开始扫描（F5）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Connect &amp;all</source>
        <translation>全部连接(&amp;A)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Open every device found in a tab of its own</source>
        <translation>在各自的标签页中打开找到的每台设备</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Close</source>
        <translation>关闭</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Conflicts and ports where nothing was found:</source>
        <translation>冲突及未找到设备的端口：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Link</source>
        <translation>链路</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Port</source>
        <translation>端口</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Rate</source>
        <translation>速率</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Family</source>
        <translation>系列</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Model</source>
        <translation>型号</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Serial number</source>
        <translation>序列号</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Address / node</source>
        <translation>地址 / 节点</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Firmware</source>
        <translation>固件</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Serial: baud; CAN: bit/s</source>
        <translation>串口：波特率；CAN：bit/s</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+176"/>
        <source>Connect</source>
        <translation>连接</translation>
    </message>
    <message>
        <location line="-174"/>
        <source>Press Sweep to look at every port and bus.</source>
        <translation>按“扫描”检查所有端口和总线。</translation>
    </message>
    <message>
        <location line="+100"/>
        <source>&quot;%1&quot; is not PLUGIN:INTERFACE (e.g. socketcan:can0): correct the CAN buses field.</source>
        <translation>“%1”不是 插件:接口 格式（例如 socketcan:can0）：请更正 CAN 总线一栏。</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>No serial port and no CAN bus to sweep: plug in an adapter, or name ports and buses above (or tick Simulated bench).</source>
        <translation>没有可扫描的串口或 CAN 总线：请插入适配器，或在上方填写端口和总线（或勾选“模拟测试台”）。</translation>
    </message>
    <message numerus="yes">
        <location line="+4"/>
        <source>Sweeping %n port(s)</source>
        <translation>
            <numerusform>正在扫描 %n 个端口</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+0"/>
        <source> and %n CAN bus(es)…</source>
        <translation>
            <numerusform>和 %n 条 CAN 总线…</numerusform>
        </translation>
    </message>
    <message>
        <location line="+28"/>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Serial</source>
        <translation>串口</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Modbus RTU</source>
        <translation>Modbus RTU</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CAN</source>
        <translation>CAN</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 kbit/s</source>
        <translation>%1 kbit/s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>heard without errors at this rate</source>
        <translation>在此波特率下监听无错误</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 baud</source>
        <translation>%1 波特</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>node %1</source>
        <translation>节点 %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Open this device in a tab of its own</source>
        <translation>在单独的标签页中打开此设备</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Could not connect %1: %2</source>
        <translation>无法连接 %1：%2</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 opened in its own tab.</source>
        <translation>%1 已在单独的标签页中打开。</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Two devices at this address: %1</source>
        <translation>此地址上有两台设备：%1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Conflict on %1, %2 %3: %4 What to do: %5</source>
        <translation>%1 上的冲突，%2 %3：%4 处理方法：%5</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>node</source>
        <translation>节点</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>address</source>
        <translation>地址</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>busy</source>
        <translation>被占用</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>silent</source>
        <translation>无应答</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>garbage</source>
        <translation>乱码</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no permission</source>
        <translation>无权限</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>could not open</source>
        <translation>无法打开</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>out of time</source>
        <translation>超时</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cancelled</source>
        <translation>已取消</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 (%2): %3</source>
        <translation>%1（%2）：%3</translation>
    </message>
    <message numerus="yes">
        <location line="+10"/>
        <source>%n device(s) found</source>
        <translation>
            <numerusform>找到 %n 台设备</numerusform>
        </translation>
    </message>
    <message>
        <location line="+0"/>
        <source> in %1 s.</source>
        <translation>，用时 %1 s。</translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source> %n conflict(s): see below, in red.</source>
        <translation>
            <numerusform> %n 处冲突：见下方红色部分。</numerusform>
        </translation>
    </message>
    <message>
        <location line="+2"/>
        <source> Cancelled: what was found so far is listed.</source>
        <translation>已取消：列出的是目前已找到的设备。</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::FirmwareUpdateDialog</name>
    <message>
        <location filename="../ui/firmware/firmware_update_dialog.cpp" line="+37"/>
        <source>unknown</source>
        <translation>未知</translation>
    </message>
    <message>
        <location line="+10"/>
        <location line="+166"/>
        <source>Firmware update on %1</source>
        <translation>%1 上的固件升级</translation>
    </message>
    <message>
        <location line="-161"/>
        <source>Serial port %1 (KBOOT bootloader)</source>
        <translation>串口 %1（KBOOT 引导程序）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CAN bus (CANopen SDO to object 0x1F51)</source>
        <translation>CAN 总线（CANopen SDO 写入对象 0x1F51）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>How the firmware reaches the module: its serial port, or a CAN adapter on the module&apos;s CANopen bus</source>
        <translation>固件传送到模块的方式：通过模块的串口，或通过接在模块 CANopen 总线上的 CAN 适配器</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Link:</source>
        <translation>链路：</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Intel HEX (.hex) or raw binary (.bin)</source>
        <translation>Intel HEX 文件 (.hex) 或原始二进制文件 (.bin)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Choose...</source>
        <translation>选择...</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Demo image</source>
        <translation>演示固件</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Simulated module only: write an application image of firmware 1.7.2 that the simulated bootloader accepts, and choose it</source>
        <translation>仅限模拟模块：写入一个固件版本 1.7.2 的应用程序映像（模拟引导程序可接受）并选中它</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>File:</source>
        <translation>文件：</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>A .bin file has no addresses: the flash address of its first byte</source>
        <translation>.bin 文件不含地址信息：此处填写其第一个字节的闪存地址</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Start of a .bin:</source>
        <translation>.bin 起始地址：</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>no file chosen</source>
        <translation>未选择文件</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Image:</source>
        <translation>固件映像：</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1, firmware %2, bootloader %3</source>
        <translation>%1，固件 %2，引导程序 %3</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>read when the update starts</source>
        <translation>升级开始时读取</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Module:</source>
        <translation>模块：</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+252"/>
        <source>ready</source>
        <translation>就绪</translation>
    </message>
    <message>
        <location line="-250"/>
        <source>Step:</source>
        <translation>步骤：</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Progress:</source>
        <translation>进度：</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Speed:</source>
        <translation>速度：</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Update</source>
        <translation>升级</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+299"/>
        <source>Close</source>
        <translation>关闭</translation>
    </message>
    <message>
        <location line="-264"/>
        <source>CAN bus</source>
        <translation>CAN 总线</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>The Qt CAN bus plugin of the adapter (socketcan for Linux CAN interfaces)</source>
        <translation>适配器对应的 Qt CAN 总线插件（Linux CAN 接口用 socketcan）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Plugin:</source>
        <translation>插件：</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The adapter&apos;s interface name, e.g. can0</source>
        <translation>适配器的接口名称，例如 can0</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Interface:</source>
        <translation>接口：</translation>
    </message>
    <message>
        <location line="+6"/>
        <source> bit/s</source>
        <translation> bit/s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>as configured</source>
        <translation>沿用接口设置</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The bus bit rate in bit/s (the HiPNUC CANopen default is 500000 bit/s); 0 leaves the interface&apos;s setting</source>
        <translation>总线波特率，单位 bit/s（HiPNUC CANopen 默认为 500000 bit/s）；0 表示沿用接口当前的设置</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Bit rate:</source>
        <translation>波特率：</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The module&apos;s CANopen node ID, 1..127 (HiPNUC default 8)</source>
        <translation>模块的 CANopen 节点 ID，1..127（HiPNUC 默认为 8）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Node:</source>
        <translation>节点：</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>Firmware update over CAN</source>
        <translation>通过 CAN 更新固件</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>The demo image could not be written to %1: %2. Free some space in the temporary folder and try again.</source>
        <translation>无法将演示固件写入 %1：%2。请清理临时文件夹的空间后重试。</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Choose the firmware</source>
        <translation>选择固件</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Firmware (*.hex *.ihex *.bin);;All files (*)</source>
        <translation>固件 (*.hex *.ihex *.bin);;所有文件 (*)</translation>
    </message>
    <message>
        <location line="+16"/>
        <location line="+7"/>
        <source>refused: %1</source>
        <translation>被拒绝：%1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 bytes from %2 to %3, CRC-32 %4; target model: not recorded in the file</source>
        <translation>%1 字节，地址 %2 至 %3，CRC-32 %4；目标型号：文件中未记录</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>waiting for the tab to close the port...</source>
        <translation>正在等待标签页关闭端口...</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>cancelling after the current packet...</source>
        <translation>将在当前数据包完成后取消...</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>%1 of %2 bytes</source>
        <translation>%1 / %2 字节</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 bytes/s</source>
        <translation>%1 字节/秒</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 bytes/s, %2 s left</source>
        <translation>%1 字节/秒，剩余 %2 s</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>firmware %1 → %2 (new); verification: %3</source>
        <translation>固件 %1 → %2（新）；校验方式：%3</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>CRC-32 reported by the bootloader</source>
        <translation>引导程序报告的 CRC-32</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>none by the bootloader; the application restarted</source>
        <translation>引导程序未校验；应用程序已重新启动</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1, firmware %2 (new), bootloader %3</source>
        <translation>%1，固件 %2（新），引导程序 %3</translation>
    </message>
    <message>
        <location line="-7"/>
        <location line="+10"/>
        <source>Done: %1</source>
        <translation>完成：%1</translation>
    </message>
    <message>
        <location line="-10"/>
        <location line="+10"/>
        <source>Not updated: %1</source>
        <translation>未升级：%1</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::GyroScaleWizard</name>
    <message>
        <location filename="../ui/calibration/gyro_scale_wizard.cpp" line="+26"/>
        <source>Gyro scale factor calibration</source>
        <translation>陀螺仪标度因数校准</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Preparation</source>
        <translation>准备工作</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&lt;ul&gt;&lt;li&gt;Place the module, with the robot or vehicle it is fixed to, on a level, flat floor.&lt;/li&gt;&lt;li&gt;Keep the temperature steady and avoid vibration (motors off).&lt;/li&gt;&lt;li&gt;Mark the start position: you must stop on the same mark, within 5 deg.&lt;/li&gt;&lt;li&gt;Turn at an even 20-100 deg/s (5-20 s per turn), in either direction, without pausing.&lt;/li&gt;&lt;li&gt;More turns give a smaller error: 720 deg (2 turns) to 1800 deg (5 turns).&lt;/li&gt;&lt;/ul&gt;Keep the module still for a few seconds after pressing Start: ImuDesk measures the gyro bias first.</source>
        <translation>&lt;ul&gt;&lt;li&gt;将模块连同其所固定的机器人或车辆放在水平、平坦的地面上。&lt;/li&gt;&lt;li&gt;保持温度稳定，避免振动（关闭电机）。&lt;/li&gt;&lt;li&gt;标记起始位置：必须停在同一标记处，误差在 5 deg 以内。&lt;/li&gt;&lt;li&gt;以 20-100 deg/s 匀速转动（每圈 5-20 s），方向不限，中途不要停顿。&lt;/li&gt;&lt;li&gt;圈数越多，误差越小：720 deg（2 圈）到 1800 deg（5 圈）。&lt;/li&gt;&lt;/ul&gt;按下“开始”后请保持模块静止几秒钟：ImuDesk 会先测量陀螺仪零偏。</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Turn on HI91 at 100 Hz (LOG HI91 ONTIME 0.01)</source>
        <translation>以 100 Hz 打开 HI91（LOG HI91 ONTIME 0.01）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Sends LOG HI91 ONTIME 0.01: the float IMU frame, gyroscope included, every 10 ms. Until SAVECONFIG it lasts until the module restarts.</source>
        <translation>发送 LOG HI91 ONTIME 0.01：每 10 ms 输出一帧浮点 IMU 数据（含陀螺仪）。未执行 SAVECONFIG 时，模块重启后失效。</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Turn the module</source>
        <translation>转动模块</translation>
    </message>
    <message>
        <location line="+6"/>
        <source> deg</source>
        <translation> deg</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Start</source>
        <translation>开始</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stop</source>
        <translation>停止</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%v of %m deg</source>
        <translation>%v / %m deg</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>rate %v deg/s (band 20-100)</source>
        <translation>角速度 %v deg/s（范围 20-100）</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Angle:</source>
        <translation>角度：</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>Result</source>
        <translation>结果</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>The module refused LOG HI91 ONTIME 0.01 (%1). Check the output in Device ▸ Configuration.</source>
        <translation>模块拒绝了 LOG HI91 ONTIME 0.01（%1）。请在“设备 ▸ 配置”中检查输出设置。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>no answer</source>
        <translation>无应答</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Gyroscope data: checking what the module sends…</source>
        <translation>陀螺仪数据：正在检查模块的输出…</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>Gyroscope data: %1 Hz. Ready: ImuDesk will follow the turn.</source>
        <translation>陀螺仪数据：%1 Hz。就绪：ImuDesk 将跟踪转动过程。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>No gyroscope data arrives: the module&apos;s calibration still works, but ImuDesk cannot show the angle turned or when to stop. Turn the HI91 output on.</source>
        <translation>未收到陀螺仪数据：模块自身的校准仍可进行，但 ImuDesk 无法显示已转过的角度和停止时机。请打开 HI91 输出。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Gyroscope data: %1 Hz, too slow to follow the turn (ImuDesk needs %2 Hz or more). Turn the HI91 output on at 100 Hz.</source>
        <translation>陀螺仪数据：%1 Hz，太慢，无法跟踪转动（ImuDesk 需要 %2 Hz 或以上）。请以 100 Hz 打开 HI91 输出。</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Sending LOG HI91 ONTIME 0.01…</source>
        <translation>正在发送 LOG HI91 ONTIME 0.01…</translation>
    </message>
    <message>
        <location line="+67"/>
        <source>%1 deg turned (%2 turns), rate %3 deg/s %4</source>
        <translation>已转动 %1 deg（%2 圈），角速度 %3 deg/s %4</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>(in band)</source>
        <translation>（在范围内）</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>(outside 20-100 deg/s)</source>
        <translation>（超出 20-100 deg/s）</translation>
    </message>
    <message>
        <location line="+54"/>
        <source>The device rejected the run: %1</source>
        <translation>设备拒绝了本次校准：%1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The device accepted the run, but ImuDesk saw no complete turn to check it.</source>
        <translation>设备已接受本次校准，但 ImuDesk 未检测到完整的一圈转动，无法核验。</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>The device accepted the calibration (OK).</source>
        <translation>设备已接受校准结果（OK）。</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>The device rejected the run (ERR).</source>
        <translation>设备拒绝了本次校准（ERR）。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>ImuDesk&apos;s estimate from the same samples: %1</source>
        <translation>ImuDesk 根据相同样本得出的估计值：%1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>ImuDesk saw no complete turn, so it has no estimate of its own.</source>
        <translation>ImuDesk 未检测到完整的一圈转动，因此没有自己的估计值。</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::HeadingDial</name>
    <message>
        <location filename="../ui/attitude/heading_dial.cpp" line="+25"/>
        <source>Heading dial</source>
        <translation>航向角表盘</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>%1°</source>
        <translation>%1°</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>no data</source>
        <translation>无数据</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>pitch %1°  roll %2°</source>
        <translation>俯仰角 %1°  横滚角 %2°</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>N</source>
        <translation>N</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>E</source>
        <translation>E</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>S</source>
        <translation>S</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>W</source>
        <translation>W</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::Hec495CalibrationWizard</name>
    <message>
        <location filename="../ui/calibration/hec495_calibration_wizard.cpp" line="+44"/>
        <source>Suits: the compass and its mount can be turned to the poses of the table. Good results; in a complex magnetic environment slightly less accurate than all-orientation. Limit: pitch must exceed 45 deg and roll 30 deg. The manual recommends trying this method first.</source>
        <translation>适用：罗盘及其安装结构能转到表中的各个姿态。效果良好；在复杂磁场环境中精度略低于全姿态校准。限制：俯仰角须超过 45 deg，横滚角须超过 30 deg。手册建议优先尝试此方法。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Suits: the pitch and roll range of use is known; collect most points in the poses used most. Best at the chosen points; badly chosen points can spoil the calibration.</source>
        <translation>适用：已知使用时的俯仰角和横滚角范围；在最常用的姿态采集大部分点。在所选点处效果最佳；选点不当会影响校准效果。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Suits: the compass and its mount can turn to every orientation and the magnetic environment is complex. The most accurate over all attitudes.</source>
        <translation>适用：罗盘及其安装结构能转到任意姿态，且磁场环境复杂。在所有姿态下精度最高。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Suits: roll stays below 5 deg in use while pitch varies widely. Best when roll is below 5 deg. Limit: pitch must exceed 45 deg.</source>
        <translation>适用：使用时横滚角保持在 5 deg 以内，而俯仰角变化较大。横滚角小于 5 deg 时效果最佳。限制：俯仰角须超过 45 deg。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Suits: the compass only turns in a plane, pitch and roll below 2 deg. Best when it is used level.</source>
        <translation>适用：罗盘只在平面内转动，俯仰角和横滚角小于 2 deg。水平使用时效果最佳。</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>HEC495 compass calibration</source>
        <translation>HEC495 罗盘校准</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Choose the calibration method</source>
        <translation>选择校准方法</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Calibrate in the place of use, with the compass fixed in its mount: everything near it (iron, batteries, motors, cables with current) must turn together with it. Carry no phone, keys or other metal while calibrating.</source>
        <translation>请在使用现场校准，并将罗盘固定在安装结构上：其附近的所有物体（铁件、电池、电机、通电线缆）都必须随其一起转动。校准时请勿携带手机、钥匙或其他金属物品。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 (command 0x%2)</source>
        <translation>%1（命令 0x%2）</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Calibrate</source>
        <translation>校准</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Targets: inner ring pitch up (above 45 deg), middle ring level, outer ring pitch down (below -45 deg); R is the roll to hold. Green: collected; orange outline: the target the compass is at. The red needle is the heading, the blue dot the pitch, the bar below the roll.</source>
        <translation>目标：内圈为上仰（俯仰角大于 45 deg），中圈为水平，外圈为下俯（俯仰角小于 -45 deg）；R 为需保持的横滚角。绿色：已采集；橙色边框：罗盘当前所在的目标。红色指针表示航向角，蓝色圆点表示俯仰角，下方横条表示横滚角。</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Start calibration</source>
        <translation>开始校准</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Collect point</source>
        <translation>采集点</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stop</source>
        <translation>停止</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save calibration</source>
        <translation>保存校准</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Clear calibration</source>
        <translation>清除校准</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Sends the start command of the method (77 04 00 xx).</source>
        <translation>发送该方法的开始命令（77 04 00 xx）。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Manual method: stores the current pose as a calibration point (0x67).</source>
        <translation>手动方法：将当前姿态存为一个校准点（0x67）。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Abandons the run without saving (0x12).</source>
        <translation>放弃本次校准，不保存（0x12）。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Computes and stores the calibration from the points collected (0x09).</source>
        <translation>根据已采集的点计算并保存校准（0x09）。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Erases the environment calibration stored in the module (0x10).</source>
        <translation>擦除模块中保存的环境校准（0x10）。</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Save to the compass</source>
        <translation>保存到罗盘</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Not yet</source>
        <translation>暂不保存</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Keeps the run going: turn the compass to more targets, or stop without saving.</source>
        <translation>继续本次校准：把罗盘转到更多目标姿态，或停止而不保存。</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>The module collected %1 points (at most %2) by itself. Saving computes the calibration from them and replaces the compass&apos;s current calibration; this cannot be undone. Save now?</source>
        <translation>模块已自动采集 %1 个点（最多 %2 个）。保存将据此计算校准并替换罗盘当前的校准，且无法撤销。现在保存吗？</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Not saved yet: the run goes on.</source>
        <translation>尚未保存：校准继续进行。</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Result</source>
        <translation>结果</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Calibrate again</source>
        <translation>重新校准</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Then save: the module replies with its fit error (FitErr); the smaller the better, above %1 calibrate again.</source>
        <translation>然后保存：模块会返回拟合误差（FitErr）；越小越好，超过 %1 时请重新校准。</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Method: %1</source>
        <translation>方法：%1</translation>
    </message>
    <message>
        <location line="+48"/>
        <source>Starting the calibration...</source>
        <translation>正在开始校准...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Collecting a point...</source>
        <translation>正在采集点...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stopping the calibration...</source>
        <translation>正在停止校准...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Saving the calibration...</source>
        <translation>正在保存校准...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Clearing the stored calibration...</source>
        <translation>正在清除已保存的校准...</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Calibration running (%1). Turn the compass as shown; targets light up as the module collects points.</source>
        <translation>正在校准（%1）。请按图示转动罗盘；模块采集到点时，相应目标会亮起。</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Point collected.</source>
        <translation>已采集点。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Calibration stopped; nothing was saved. The module keeps its previous calibration.</source>
        <translation>校准已停止，未保存任何数据。模块保留之前的校准。</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The stored environment calibration was cleared from the module. Start a new calibration before relying on the heading near iron.</source>
        <translation>已清除模块中保存的环境校准。在铁件附近依赖航向角之前，请先重新校准。</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Calibration saved.</source>
        <translation>校准已保存。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The module answered the save command without a fit error (%1). Collect the points again and save once more.</source>
        <translation>模块响应了保存命令，但未返回拟合误差（%1）。请重新采集点并再次保存。</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>Check the cable, the power, the baud rate and the module address, then try again.</source>
        <translation>请检查线缆、电源、波特率和模块地址，然后重试。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The connection is closed: connect to the compass again, then restart the calibration.</source>
        <translation>连接已关闭：请重新连接罗盘，然后重新开始校准。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The reply was not one the manual allows: check that the device is an HEC495 and try again.</source>
        <translation>应答不符合手册规定：请确认设备为 HEC495，然后重试。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The module could not compute a calibration: too few points, or points that do not span the field. Start the calibration again and turn through more of the target poses before saving.</source>
        <translation>模块无法计算校准：点数太少，或各点未能覆盖磁场范围。请重新开始校准，并在保存前转过更多目标姿态。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The module did not take the point: no manual calibration is running, or it is full. Start the manual method first.</source>
        <translation>模块未接受该点：当前没有正在进行的手动校准，或采集点已满。请先开始手动方法。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The module refused to start this method. Stop any calibration in progress and try again.</source>
        <translation>模块拒绝启动此方法。请停止正在进行的校准，然后重试。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Try again; if it keeps failing, power the module off and on.</source>
        <translation>请重试；如仍然失败，请将模块断电后重新上电。</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Failed: %1.
%2</source>
        <translation>失败：%1。
%2</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Valid points: %1 of at most %2</source>
        <translation>有效点：%1（最多 %2）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Valid points: %1 (at least %2)</source>
        <translation>有效点：%1（至少 %2）</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>No calibration was saved.</source>
        <translation>未保存校准。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Fit error (FitErr): %1
Points used: %2
Method: %3</source>
        <translation>拟合误差（FitErr）：%1
使用点数：%2
方法：%3</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>FitErr is above %1: the manual says to calibrate again. Check that nothing magnetic moved relative to the compass during the run, that no phone or keys were near, and turn through the target poses more carefully; press &quot;Calibrate again&quot;.</source>
        <translation>FitErr 超过 %1：手册要求重新校准。请检查校准过程中没有磁性物体相对罗盘移动，附近没有手机或钥匙，并更仔细地转过各目标姿态；然后点击“重新校准”。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Good: FitErr is at most %1. The module stores and uses the calibration from now on.</source>
        <translation>良好：FitErr 不超过 %1。模块将保存此校准并从现在起使用。</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>FitErr %1 is at most %2.</source>
        <translation>FitErr %1 不超过 %2。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>FitErr %1 is above %2: the manual says to calibrate again.</source>
        <translation>FitErr %1 超过 %2：手册要求重新校准。</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::Hec495SettingsPanel</name>
    <message>
        <location filename="../ui/configuration/hec495_settings_panel.cpp" line="+130"/>
        <source>Factory reset</source>
        <translation>恢复出厂设置</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Restore the factory settings (9600 baud, address 0, declination 0, question/answer)? The session follows the module to 9600 baud.</source>
        <translation>恢复出厂设置（波特率 9600，地址 0，磁偏角 0，问答模式）？会话将随模块切换到 9600 波特率。</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Waiting for the module…</source>
        <translation>正在等待模块…</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Failed: %1</source>
        <translation>失败：%1</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>Magnetic declination</source>
        <translation>磁偏角</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Baud rate</source>
        <translation>波特率</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Output rate</source>
        <translation>输出频率</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Output content</source>
        <translation>输出内容</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Module address</source>
        <translation>模块地址</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Single reading</source>
        <translation>单次读取</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Read</source>
        <translation>读取</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ask the module for its address (manual 2.17: sent to address 0, any module answers).</source>
        <translation>向模块查询其地址（手册 2.17：发往地址 0，任何模块都会应答）。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ask the module once for the chosen angle (manual 2.1 to 2.4); the answer, in degrees, shows below.</source>
        <translation>向模块读取一次所选角度（手册 2.1 至 2.4）；应答（单位为度）显示在下方。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Pitch</source>
        <translation>俯仰</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Roll</source>
        <translation>横滚</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Heading</source>
        <translation>航向</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Pitch, roll and heading</source>
        <translation>俯仰、横滚和航向</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Set</source>
        <translation>设置</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save settings</source>
        <translation>保存设置</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Factory reset…</source>
        <translation>恢复出厂设置…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Changes apply at once and are lost at power-off unless saved.</source>
        <translation>更改立即生效，未保存则断电后丢失。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Question/answer</source>
        <translation>问答模式</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1 Hz</source>
        <translation>%1 Hz</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Default (angles)</source>
        <translation>默认（角度）</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Internal data</source>
        <translation>内部数据</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>All data (read-all record)</source>
        <translation>全部数据（完整读取记录）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>NMEA 0183</source>
        <translation>NMEA 0183</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::LanguageSwitcher</name>
    <message>
        <location filename="../ui/workspace/language_switcher.cpp" line="+54"/>
        <source>Unknown language &quot;%1&quot;; choose one of: %2.</source>
        <translation>未知语言“%1”；请选择以下之一：%2。</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>The %1 translation was not found in %2.</source>
        <translation>在 %2 中未找到 %1 翻译。</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::LineDatabaseDialog</name>
    <message>
        <location filename="../ui/station/line_database_dialog.cpp" line="+91"/>
        <source>Line database</source>
        <translation>产线数据库</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Every module this station tests is stored in its own database first (results.sqlite in the report folder); with a line database set, the station also sends each result there, and keeps it until the server has it.</source>
        <translation>本测试台测试的每个模块都会先存入自己的数据库（报告文件夹中的 results.sqlite）；设置产线数据库后，测试台还会把每个结果发送到那里，并在服务器收到之前一直保留。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Server:</source>
        <translation>服务器：</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The line&apos;s PostgreSQL database: postgresql://user@host[:port]/database. Empty: none. A password typed here (user:password@host) is stored with the station&apos;s settings as typed; put it into ~/.pgpass instead, which PostgreSQL reads by itself.</source>
        <translation>产线的 PostgreSQL 数据库：postgresql://用户@主机[:端口]/数据库。留空：不使用。在此输入的密码（用户:密码@主机）会原样保存在测试台的设置中；请改为写入 ~/.pgpass，PostgreSQL 会自行读取。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Shared artifact folder:</source>
        <translation>共享附件文件夹：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A folder every station and the office can reach (a network share): each module&apos;s PDF report and recording are copied there, checked against their SHA-256, and the line database records that copy. Empty: the files stay on this station.</source>
        <translation>每个测试台和办公室都能访问的文件夹（网络共享）：每个模块的 PDF 报告和录制文件会复制到这里，并用 SHA-256 校验，产线数据库记录这份副本。留空：文件只保留在本测试台。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Browse…</source>
        <translation>浏览…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Test connection</source>
        <translation>测试连接</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Connect to the server now, as the station will (a fresh database gets ImuDesk&apos;s tables)</source>
        <translation>现在按测试台的方式连接服务器（全新的数据库会创建 ImuDesk 的数据表）</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>A line database is a PostgreSQL server: its address starts with postgresql://</source>
        <translation>产线数据库是 PostgreSQL 服务器：地址以 postgresql:// 开头</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The password is stored with the station&apos;s settings as typed; ~/.pgpass keeps it out of them.</source>
        <translation>密码会原样保存在测试台的设置中；写入 ~/.pgpass 可避免这一点。</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Shared artifact folder</source>
        <translation>共享附件文件夹</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Connecting to %1…</source>
        <translation>正在连接 %1…</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Connected: schema %1</source>
        <translation>已连接：数据库结构版本 %1</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::LineDatabaseStatus</name>
    <message>
        <location line="+33"/>
        <source> · connecting to the line database…</source>
        <translation> · 正在连接产线数据库…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source> · upload failing: %1</source>
        <translation> · 上传失败：%1</translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source> · %n result(s) waiting to upload</source>
        <translation>
            <numerusform> · %n 个结果等待上传</numerusform>
        </translation>
    </message>
    <message>
        <location line="+1"/>
        <source> · every result uploaded</source>
        <translation> · 所有结果均已上传</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Uploading to %1 fails: %2
The results wait in this station&apos;s database and go as soon as the server answers; nothing is lost.</source>
        <translation>上传到 %1 失败：%2
结果暂存在本测试台的数据库中，服务器一有响应就会发送；不会丢失任何数据。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Results go to the line database %1.</source>
        <translation>结果会发送到产线数据库 %1。</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::LiveBridgeDialog</name>
    <message>
        <location filename="../ui/bridge/live_bridge_dialog.cpp" line="+150"/>
        <source>Live bridge</source>
        <translation>实时桥接</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Foxglove WebSocket (Foxglove, Lichtblick, PlotJuggler)</source>
        <translation>Foxglove WebSocket（Foxglove、Lichtblick、PlotJuggler）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Address:</source>
        <translation>地址(&amp;A)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>127.0.0.1 (this computer only)</source>
        <translation>127.0.0.1（仅本机）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>0.0.0.0 (every network of this computer)</source>
        <translation>0.0.0.0（本机的所有网络）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Where clients may connect from. Another address than 127.0.0.1 lets anyone on that network read the data: the Foxglove protocol has no password.</source>
        <translation>客户端可从何处连接。127.0.0.1 以外的地址允许该网络上的任何人读取数据：Foxglove 协议没有密码。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Port:</source>
        <translation>端口(&amp;P)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>TCP port of the WebSocket server (Foxglove&apos;s usual port: 8765)</source>
        <translation>WebSocket 服务器的 TCP 端口（Foxglove 常用端口：8765）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Foxglove and Lichtblick: Open connection &gt; Foxglove WebSocket, ws://127.0.0.1:%1. PlotJuggler: Streaming &gt; Foxglove Bridge. Each device&apos;s topics are /imu/&lt;serial&gt;/imu, mag, euler, status, ... as in an MCAP recording.</source>
        <translation>Foxglove 和 Lichtblick：Open connection &gt; Foxglove WebSocket，ws://127.0.0.1:%1。PlotJuggler：Streaming &gt; Foxglove Bridge。每台设备的话题为 /imu/&lt;序列号&gt;/imu、mag、euler、status 等，与 MCAP 记录相同。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>PlotJuggler UDP (JSON)</source>
        <translation>PlotJuggler UDP（JSON）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Host:</source>
        <translation>主机(&amp;H)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Computer running PlotJuggler&apos;s UDP server (Streaming &gt; UDP Server, message protocol JSON, time stamp from the field &quot;timestamp&quot;)</source>
        <translation>运行 PlotJuggler UDP 服务器的计算机（Streaming &gt; UDP Server，消息协议 JSON，时间戳取自字段 &quot;timestamp&quot;）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>P&amp;ort:</source>
        <translation>端口(&amp;O)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>UDP port PlotJuggler listens on (its default: 9870)</source>
        <translation>PlotJuggler 监听的 UDP 端口（默认：9870）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Log (clients, refused requests, dropped messages):</source>
        <translation>日志(&amp;L)（客户端、被拒绝的请求、丢弃的消息）：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Close</source>
        <translation>关闭</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Warning: %1 is not this computer only. Anyone who can reach it on the network can read the devices&apos; data: the protocol has no password.</source>
        <translation>警告：%1 不仅限本机。网络上能访问它的任何人都可以读取设备数据：该协议没有密码。</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&amp;Stop</source>
        <translation>停止(&amp;S)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>&amp;Start</source>
        <translation>开始(&amp;S)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stop the bridge (Ctrl+Shift+B opens this window)</source>
        <translation>停止桥接（Ctrl+Shift+B 打开此窗口）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Send the connected devices&apos; samples from now on</source>
        <translation>从现在起发送已连接设备的采样</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Stopped</source>
        <translation>已停止</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1
%2 device(s); samples: %3, missed: %4</source>
        <translation>%1
%2 台设备；采样：%3，遗漏：%4</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Choose the Foxglove WebSocket server, PlotJuggler UDP or both.</source>
        <translation>请选择 Foxglove WebSocket 服务器、PlotJuggler UDP 或两者。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&apos;%1&apos; is not an IP address. Use 127.0.0.1 for this computer only or 0.0.0.0 for every network.</source>
        <translation>“%1”不是 IP 地址。仅本机请用 127.0.0.1，所有网络请用 0.0.0.0。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&apos;%1&apos; is not an IP address: give the address of the computer running PlotJuggler, e.g. 127.0.0.1.</source>
        <translation>“%1”不是 IP 地址：请填写运行 PlotJuggler 的计算机地址，例如 127.0.0.1。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1
Choose another port, or close the program that uses this one.</source>
        <translation>%1
请选择其他端口，或关闭占用此端口的程序。</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::MagCalibrationWizard</name>
    <message>
        <location filename="../ui/calibration/mag_calibration_wizard.cpp" line="+42"/>
        <source>unknown</source>
        <translation>未知</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>unbounded</source>
        <translation>无界</translation>
    </message>
    <message>
        <location line="+61"/>
        <source>Magnetometer calibration</source>
        <translation>地磁校准</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Before you start</source>
        <translation>开始之前</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Calibrate the magnetometer when you use the 9-axis (AHRS) mode, where the heading follows magnetic north. Without a magnetometer calibration, or where the field is disturbed, use the 6-axis mode instead.

Best: outdoors in an open space, more than 5 m from buildings and vehicles. Acceptable: indoors, more than 30 cm from iron furniture, monitors, motors, transformers, chargers and phones.

If the module is mounted on a PCB, in a housing or on a robot, calibrate it together with them, as one rigid body: calibrating the module alone does not help once it is mounted.</source>
        <translation>使用 9 轴（AHRS）模式时请进行地磁校准，该模式下航向角以磁北为基准。未进行地磁校准或磁场受到干扰时，请改用 6 轴模式。

最佳：室外空旷处，距建筑物和车辆 5 m 以上。可接受：室内，距铁质家具、显示器、电机、变压器、充电器和手机 30 cm 以上。

如果模块安装在 PCB 上、外壳中或机器人上，请将它们作为一个刚体一起校准：模块安装后，单独校准模块没有用。</translation>
    </message>
    <message>
        <location line="+19"/>
        <location line="+263"/>
        <source>Working mode</source>
        <translation>工作模式</translation>
    </message>
    <message>
        <location line="-262"/>
        <source>The calibration needs the 9-axis (AHRS) mode, CONFIG ATT MODE 1 (the factory setting). ImuDesk reads the module&apos;s mode first and offers a switch only when it runs in a 6-axis mode; the switch sends CONFIG ATT MODE 1, SAVECONFIG and REBOOT.</source>
        <translation>校准需要 9 轴（AHRS）模式，即 CONFIG ATT MODE 1（出厂设置）。ImuDesk 先读取模块的模式，仅当其运行在 6 轴模式时才提供切换；切换会发送 CONFIG ATT MODE 1、SAVECONFIG 和 REBOOT。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Switch to 9-axis mode</source>
        <translation>切换到 9 轴模式</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>The module did not take ATT MODE 1 (%1). Check the connection and try again.</source>
        <translation>模块未接受 ATT MODE 1（%1）。请检查连接后重试。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>read back differs</source>
        <translation>回读值不一致</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>ATT MODE 1 set; saving it (SAVECONFIG)…</source>
        <translation>已设置 ATT MODE 1；正在保存（SAVECONFIG）…</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1 failed: %2. Try again, or save and restart from the Configuration panel.</source>
        <translation>%1 失败：%2。请重试，或在配置面板中保存并重启。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Saved; restarting the module (REBOOT)…</source>
        <translation>已保存；正在重启模块（REBOOT）…</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The module restarts in the 9-axis mode; reading it back…</source>
        <translation>模块以 9 轴模式重启；正在回读…</translation>
    </message>
    <message>
        <location line="+9"/>
        <location line="+195"/>
        <source>Environment check</source>
        <translation>环境检查</translation>
    </message>
    <message>
        <location line="-194"/>
        <source>At the calibration spot, turn the module slowly through many orientations. The module&apos;s own iron is taken out of the field first; what is left must be the Earth&apos;s field (20-65 µT), the same in every orientation (within 10 µT), and steady while the module is still.</source>
        <translation>在校准位置把模块缓慢转过多个朝向。先从磁场中去除模块自身的铁磁干扰；剩下的必须是地磁场（20-65 µT），在各朝向上相同（相差不超过 10 µT），并且在模块静止时保持稳定。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Raw |B|: the field strength as measured, the module&apos;s own iron included. Field at the spot: the strength once that iron is fitted out. Spread: how much it differs between orientations (5th to 95th percentile). Change while still: |B| drift while the gyro shows no turn.</source>
        <translation>原始 |B|：测得的磁场强度，包含模块自身的铁磁干扰。此处磁场：拟合去除该干扰后的强度。离散：各朝向之间的差异（第 5 到第 95 百分位）。静止时变化：陀螺仪显示未转动时 |B| 的漂移。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The raw field as it comes from the module (µT), one dot per sample</source>
        <translation>模块输出的原始磁场（µT），每个样本一个点</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Coverage: share of the 80 sphere cells the field direction has pointed into, with the module&apos;s own iron fitted out by the live fit (before a usable fit: the raw directions). The sphere, its readout and the verdict give this one figure. Largest gap: radius of the biggest uncovered area. Raw |B|: the field strength before calibration (its spread is the iron the fit removes). Fit: the field and the residual of ImuDesk&apos;s fit on the samples so far, refreshed every second. Samples: every sample taken for ImuDesk&apos;s fit (the sphere draws a thinned share of them).</source>
        <translation>覆盖率：磁场方向已指向的 80 个球面单元所占比例，模块自身的铁磁已由实时拟合去除（尚无可用拟合时：原始方向）。球面、其读数和结论给出的是同一个数值。最大空缺：最大未覆盖区域的半径。原始 |B|：校准前的磁场强度（其波动即拟合要去除的铁磁）。拟合：ImuDesk 对目前样本拟合的磁场和残差，每秒刷新。样本：为 ImuDesk 拟合采集的全部样本（球面只绘制其中抽稀的一部分）。</translation>
    </message>
    <message>
        <location line="+56"/>
        <source>Place the module level (roll and pitch within 15 deg) and turn it slowly one full turn (360 deg). The heading must change continuously, without jumps of more than 10 deg; within +-5 deg of the true directions is acceptable. Turns made while the module is tilted or the field is disturbed are not judged: the check says so.</source>
        <translation>将模块水平放置（横滚和俯仰在 15° 以内），缓慢转动一整圈（360°）。航向必须连续变化，跳变不得超过 10°；与真实方向相差 ±5° 以内即可接受。模块倾斜或磁场受扰时的转动不作判定：检查会给出提示。</translation>
    </message>
    <message>
        <location line="+117"/>
        <source>read from the module; a switch to 9-axis is offered when needed</source>
        <translation>从模块读取；需要时提供切换到 9 轴模式</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>turn the module at the spot: the field is judged with its own iron taken out</source>
        <translation>在该位置转动模块：去除其自身铁磁干扰后判断磁场</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>slowly about every axis until the sphere is covered, usually 30-60 s; %1</source>
        <translation>绕每个轴缓慢转动直到覆盖整个球面，通常 30-60 s；%1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the module calibrates itself at the same time (CONFIG MCAL, firmware %1)</source>
        <translation>模块同时进行自身的校准（CONFIG MCAL，固件 %1）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>firmware %1 calibrates in the background in 9-axis mode</source>
        <translation>固件 %1 在 9 轴模式下于后台校准</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>ImuDesk&apos;s fit and the module&apos;s own verdict, side by side; saved with the samples</source>
        <translation>ImuDesk 的拟合与模块自身的结论并排显示；与样本一起保存</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>one level turn: the heading must follow without jumps</source>
        <translation>水平转一圈：航向必须连续跟随，没有跳变</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>heading from the gyro alone: it drifts, the magnetometer is not used</source>
        <translation>航向仅来自陀螺仪：会漂移，不使用磁力计</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>heading follows magnetic north: needs this calibration</source>
        <translation>航向跟随磁北：需要本校准</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>6-axis, for legged robots (firmware 1.7.x)</source>
        <translation>6 轴，用于足式机器人（固件 1.7.x）</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>◀ the module</source>
        <translation>◀ 本模块</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>ATT MODE</source>
        <translation>ATT MODE</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Heading</source>
        <translation>航向</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Raw |B| now</source>
        <translation>当前原始 |B|</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>µT</source>
        <translation>µT</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Field at the spot</source>
        <translation>此处磁场</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>µT (Earth: 20–65)</source>
        <translation>µT（地磁场：20–65）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Module&apos;s own iron</source>
        <translation>模块自身铁磁干扰</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>µT, removed by the calibration</source>
        <translation>µT，由校准去除</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Spread</source>
        <translation>离散</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>µT between orientations (≤ 10)</source>
        <translation>µT，各朝向之间（≤ 10）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Change while still</source>
        <translation>静止时变化</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>µT (≤ 3)</source>
        <translation>µT（≤ 3）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Directions</source>
        <translation>方向</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>% of the sphere</source>
        <translation>% 的球面</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>&lt;tr&gt;&lt;td&gt;Predicted heading error&lt;/td&gt;&lt;td align=right&gt;&lt;b&gt;%1°&lt;/b&gt;&lt;/td&gt;&lt;td&gt;level module, 68 %; 95 %: %2°&lt;/td&gt;&lt;/tr&gt;</source>
        <translation>&lt;tr&gt;&lt;td&gt;预测航向误差&lt;/td&gt;&lt;td align=right&gt;&lt;b&gt;%1°&lt;/b&gt;&lt;/td&gt;&lt;td&gt;水平模块，68 %；95 %：%2°&lt;/td&gt;&lt;/tr&gt;</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>&lt;tr&gt;&lt;td&gt;Coverage&lt;/td&gt;&lt;td align=right&gt;&lt;b&gt;%1 %&lt;/b&gt;&lt;/td&gt;&lt;td&gt;(%2 of %3 cells, the module&apos;s iron fitted out)&lt;/td&gt;&lt;/tr&gt;</source>
        <translation>&lt;tr&gt;&lt;td&gt;覆盖率&lt;/td&gt;&lt;td align=right&gt;&lt;b&gt;%1 %&lt;/b&gt;&lt;/td&gt;&lt;td&gt;（%2/%3 个单元，已去除模块自身铁磁）&lt;/td&gt;&lt;/tr&gt;</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&lt;tr&gt;&lt;td&gt;Coverage&lt;/td&gt;&lt;td align=right&gt;&lt;b&gt;%1 %&lt;/b&gt;&lt;/td&gt;&lt;td&gt;(%2 of %3 cells, raw directions: no usable fit yet)&lt;/td&gt;&lt;/tr&gt;</source>
        <translation>&lt;tr&gt;&lt;td&gt;覆盖率&lt;/td&gt;&lt;td align=right&gt;&lt;b&gt;%1 %&lt;/b&gt;&lt;/td&gt;&lt;td&gt;（%2/%3 个单元，原始方向：尚无可用拟合）&lt;/td&gt;&lt;/tr&gt;</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>&lt;tr&gt;&lt;td&gt;Predicted heading error&lt;/td&gt;&lt;td align=right&gt;&lt;b&gt;%1°&lt;/b&gt;&lt;/td&gt;&lt;td&gt;level, 68 % (95 %: %4°; pass &amp;lt; %2°, refused &amp;gt; %3°)&lt;/td&gt;&lt;/tr&gt;</source>
        <translation>&lt;tr&gt;&lt;td&gt;预测航向误差&lt;/td&gt;&lt;td align=right&gt;&lt;b&gt;%1°&lt;/b&gt;&lt;/td&gt;&lt;td&gt;水平，68 %（95 %：%4°；通过 &amp;lt; %2°，拒绝 &amp;gt; %3°）&lt;/td&gt;&lt;/tr&gt;</translation>
    </message>
    <message>
        <location line="+143"/>
        <source>The module&apos;s own calibration (MCAL) passed on the turns it collected, but its heading jumps in a level turn here: the field or the module&apos;s mounting changed since, or the collected turns did not represent this place.</source>
        <translation>模块自身的校准（MCAL）在其采集的转动上通过了，但此处水平转动时其航向跳变：之后磁场或模块安装发生了变化，或采集的转动不能代表此处。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>ImuDesk&apos;s fit passed on the collected samples, but the module computes its heading with its own calibration, which was not run to its end here: run the module&apos;s calibration (MCAL) too.</source>
        <translation>ImuDesk 的拟合在采集的样本上通过了，但模块用自身的校准计算航向，而该校准此处未运行完毕：请同时运行模块的校准（MCAL）。</translation>
    </message>
    <message numerus="yes">
        <location line="+70"/>
        <source>The device now corrects its own output, so ImuDesk&apos;s fit keeps the %n raw sample(s) collected before.</source>
        <translation>
            <numerusform>设备现在会自行校正其输出，因此 ImuDesk 的拟合只保留此前采集的 %n 个原始样本。</numerusform>
        </translation>
    </message>
    <message>
        <location line="+32"/>
        <source>still running</source>
        <translation>仍在运行</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The device&apos;s own calibration (CONFIG MCAL START): %1. %2</source>
        <translation>设备自身的校准（CONFIG MCAL START）：%1。%2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The device&apos;s own calibration (in the background): %1. %2</source>
        <translation>设备自身的校准（后台）：%1。%2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Last reply: STAT=%1, PROGRESS=%2.</source>
        <translation>最后一次应答：STAT=%1，PROGRESS=%2。</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>The device&apos;s own calibration (MCAL) was not run; the verdict above is ImuDesk&apos;s fit alone.</source>
        <translation>未运行设备自身的校准（MCAL）；上面的结论仅为 ImuDesk 的拟合。</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Hard iron: %1, %2, %3 µT
Field: %4 µT
Fit error: %5 %
Residual RMS: %6 µT
</source>
        <translation>硬铁：%1, %2, %3 µT
磁场：%4 µT
拟合误差：%5 %
残差 RMS：%6 µT
</translation>
    </message>
    <message>
        <location line="-584"/>
        <location line="+179"/>
        <source>Turn the module</source>
        <translation>转动模块</translation>
    </message>
    <message>
        <location line="-178"/>
        <source>Keep it in place and turn it slowly (20-100 deg/s) at least one full turn about each axis, until the sphere is green all over. Usually 30-60 s.</source>
        <translation>保持模块位置不变，缓慢转动（20-100 deg/s），绕每个轴至少转一整圈，直到球面全部变绿。通常需要 30-60 s。</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Start the device&apos;s calibration</source>
        <translation>启动设备校准</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Fit ImuDesk&apos;s calibration now</source>
        <translation>立即用 ImuDesk 拟合校准</translation>
    </message>
    <message>
        <location line="+10"/>
        <location line="+155"/>
        <source>Result</source>
        <translation>结果</translation>
    </message>
    <message>
        <location line="-126"/>
        <location line="+127"/>
        <source>Heading check</source>
        <translation>航向角检查</translation>
    </message>
    <message>
        <location line="+272"/>
        <location line="+16"/>
        <source>ImuDesk&apos;s fit: %1. %2</source>
        <translation>ImuDesk 拟合：%1。%2</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Device: STAT=%1 PROGRESS=%2
%3</source>
        <translation>设备：STAT=%1 PROGRESS=%2
%3</translation>
    </message>
    <message>
        <location line="-385"/>
        <source>Reading the working mode from the module (LOG COMCONFIG)…</source>
        <translation>正在从模块读取工作模式（LOG COMCONFIG）…</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>The working mode could not be read: %1. Check the connection, then press Back and Next to read it again, or switch to the 9-axis mode anyway.</source>
        <translation>无法读取工作模式：%1。请检查连接，然后按“上一步”和“下一步”重新读取，或直接切换到 9 轴模式。</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>The module runs in the 9-axis (AHRS) mode, ATT MODE 1: nothing to change. Press Next.</source>
        <translation>模块运行在 9 轴（AHRS）模式，ATT MODE 1：无需更改。请按“下一步”。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The module runs in a 6-axis mode (ATT MODE %1): its heading ignores the magnetometer. Switch to the 9-axis mode before you calibrate.</source>
        <translation>模块运行在 6 轴模式（ATT MODE %1）：其航向不使用磁力计。校准前请切换到 9 轴模式。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>not reported</source>
        <translation>未报告</translation>
    </message>
    <message>
        <location line="+39"/>
        <source>So far: %1. %2</source>
        <translation>目前：%1。%2</translation>
    </message>
    <message>
        <location line="+83"/>
        <source>&lt;tr&gt;&lt;td&gt;ImuDesk&apos;s fit&lt;/td&gt;&lt;td align=right&gt;&lt;b&gt;%1&lt;/b&gt;&lt;/td&gt;&lt;td&gt;&lt;/td&gt;&lt;/tr&gt;</source>
        <translation>&lt;tr&gt;&lt;td&gt;ImuDesk 拟合&lt;/td&gt;&lt;td align=right&gt;&lt;b&gt;%1&lt;/b&gt;&lt;/td&gt;&lt;td&gt;&lt;/td&gt;&lt;/tr&gt;</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&lt;tr&gt;&lt;td&gt;Coverage&lt;/td&gt;&lt;td align=right&gt;&lt;b&gt;%1 %&lt;/b&gt;&lt;/td&gt;&lt;td&gt;of the field directions&lt;/td&gt;&lt;/tr&gt;</source>
        <translation>&lt;tr&gt;&lt;td&gt;覆盖率&lt;/td&gt;&lt;td align=right&gt;&lt;b&gt;%1 %&lt;/b&gt;&lt;/td&gt;&lt;td&gt;磁场方向&lt;/td&gt;&lt;/tr&gt;</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>&lt;tr&gt;&lt;td&gt;Largest gap&lt;/td&gt;&lt;td align=right&gt;&lt;b&gt;%1°&lt;/b&gt;&lt;/td&gt;&lt;td&gt;radius&lt;/td&gt;&lt;/tr&gt;</source>
        <translation>&lt;tr&gt;&lt;td&gt;最大空缺&lt;/td&gt;&lt;td align=right&gt;&lt;b&gt;%1°&lt;/b&gt;&lt;/td&gt;&lt;td&gt;半径&lt;/td&gt;&lt;/tr&gt;</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&lt;tr&gt;&lt;td&gt;Raw |B|&lt;/td&gt;&lt;td align=right&gt;&lt;b&gt;%1–%2&lt;/b&gt;&lt;/td&gt;&lt;td&gt;µT&lt;/td&gt;&lt;/tr&gt;</source>
        <translation>&lt;tr&gt;&lt;td&gt;原始 |B|&lt;/td&gt;&lt;td align=right&gt;&lt;b&gt;%1–%2&lt;/b&gt;&lt;/td&gt;&lt;td&gt;µT&lt;/td&gt;&lt;/tr&gt;</translation>
    </message>
    <message>
        <location line="-27"/>
        <location line="+31"/>
        <source>&lt;tr&gt;&lt;td&gt;Fitted field&lt;/td&gt;&lt;td align=right&gt;&lt;b&gt;%1&lt;/b&gt;&lt;/td&gt;&lt;td&gt;µT&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;Fit residual&lt;/td&gt;&lt;td align=right&gt;&lt;b&gt;%2&lt;/b&gt;&lt;/td&gt;&lt;td&gt;µT RMS (%3 %)&lt;/td&gt;&lt;/tr&gt;</source>
        <translation>&lt;tr&gt;&lt;td&gt;拟合磁场&lt;/td&gt;&lt;td align=right&gt;&lt;b&gt;%1&lt;/b&gt;&lt;/td&gt;&lt;td&gt;µT&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;拟合残差&lt;/td&gt;&lt;td align=right&gt;&lt;b&gt;%2&lt;/b&gt;&lt;/td&gt;&lt;td&gt;µT RMS（%3 %）&lt;/td&gt;&lt;/tr&gt;</translation>
    </message>
    <message>
        <location line="-22"/>
        <location line="+34"/>
        <source>&lt;tr&gt;&lt;td&gt;Samples&lt;/td&gt;&lt;td align=right&gt;&lt;b&gt;%1&lt;/b&gt;&lt;/td&gt;&lt;td&gt;&lt;/td&gt;&lt;/tr&gt;</source>
        <translation>&lt;tr&gt;&lt;td&gt;样本数&lt;/td&gt;&lt;td align=right&gt;&lt;b&gt;%1&lt;/b&gt;&lt;/td&gt;&lt;td&gt;&lt;/td&gt;&lt;/tr&gt;</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Setting ATT MODE 1…</source>
        <translation>正在设置 ATT MODE 1…</translation>
    </message>
    <message>
        <location line="+275"/>
        <source>No fit yet.</source>
        <translation>尚无拟合结果。</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>level module; pass below %1°, refused above %2°</source>
        <translation>水平放置；低于 %1° 通过，高于 %2° 拒绝</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>level module; a warning above %1°</source>
        <translation>水平放置；高于 %1° 给出警告</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Predicted heading error: %1° in 68 % of cases, %5° in 95 % (%2)
Hard-iron uncertainty: +-%3 µT
Soft-iron uncertainty: +-%4 %
</source>
        <translation>预测航向误差：68 % 的情况下 %1°，95 % 的情况下 %5°（%2）
硬铁不确定度：+-%3 µT
软铁不确定度：+-%4 %
</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>kept from before</source>
        <translation>沿用之前的</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Coverage: %1 %
Eigenvalue ratio: %2
Samples: %3</source>
        <translation>覆盖率：%1 %
特征值比：%2
样本数：%3</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>What to check:</source>
        <translation>检查要点：</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::MagSphereView</name>
    <message>
        <location filename="../ui/calibration/mag_sphere_view.cpp" line="+23"/>
        <source>Magnetometer samples on a sphere: cells turn green as the field directions cover them. Drag to turn the view, double-click to reset it.</source>
        <translation>球面上的磁力计样本：被磁场方向覆盖到的单元格会变绿。拖动可旋转视图，双击可复位视图。</translation>
    </message>
    <message>
        <location line="+88"/>
        <source>|B| %1 µT   coverage %2 %   %3 samples</source>
        <translation>|B| %1 µT   覆盖率 %2 %   %3 个样本</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1 samples, raw (no usable correction)</source>
        <translation>%1 个样本，原始数据（无可用的校正）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 samples   coverage %2 %</source>
        <translation>%1 个样本   覆盖率 %2 %</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Predicted heading error %1°</source>
        <translation>预测航向误差 %1°</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::MainWindow</name>
    <message>
        <location filename="../ui/workspace/main_window.cpp" line="+406"/>
        <source>Choose a port first.</source>
        <translation>请先选择串口。</translation>
    </message>
    <message>
        <location line="+103"/>
        <source>ImuDesk</source>
        <translation>ImuDesk</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>About ImuDesk</source>
        <translation>关于 ImuDesk</translation>
    </message>
    <message>
        <location line="-152"/>
        <source>No device family simulates &quot;%1&quot;.</source>
        <translation>没有设备系列能模拟“%1”。</translation>
    </message>
    <message>
        <location line="+153"/>
        <source>&lt;h3&gt;ImuDesk %1&lt;/h3&gt;&lt;p&gt;A bench tool for IMU, AHRS and compass modules on serial, RS-485 Modbus and CAN links: live values and charts, settings, calibration, firmware updates, recordings and simulated devices.&lt;/p&gt;&lt;p&gt;Built with Qt %2.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;ImuDesk %1&lt;/h3&gt;&lt;p&gt;面向串口、RS-485 Modbus 和 CAN 链路上的 IMU、AHRS 与罗盘模块的台架工具：实时数值与曲线、设置、校准、固件升级、记录以及模拟设备。&lt;/p&gt;&lt;p&gt;基于 Qt %2 构建。&lt;/p&gt;</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>ImuDesk – IMU bench tool</source>
        <translation>ImuDesk – IMU 测试工具</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 – %2</source>
        <translation>%1 – %2</translation>
    </message>
    <message>
        <location line="+93"/>
        <source>%1, serial %2</source>
        <translation>%1，序列号 %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 (tab %2)</source>
        <translation>%1（标签页 %2）</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>Save screenshot</source>
        <translation>保存截图</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PNG images (*.png)</source>
        <translation>PNG 图像 (*.png)</translation>
    </message>
    <message>
        <location line="+149"/>
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
        <source>&amp;New connection tab</source>
        <translation>新建连接标签页(&amp;N)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Open a tab for another device; each tab has its own connection and views</source>
        <translation>为另一台设备打开一个标签页；每个标签页都有独立的连接和视图</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Close tab</source>
        <translation>关闭标签页(&amp;C)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save &amp;screenshot…</source>
        <translation>保存截图(&amp;S)…</translation>
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
        <source>&amp;Take one sample</source>
        <translation>采集一次数据(&amp;T)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Send LOG … ONMARK ONCE: the module outputs one frame of the type it sends, as a pulse on SYNC_IN would trigger</source>
        <translation>发送 LOG … ONMARK ONCE：模块按其当前输出类型输出一帧数据，与 SYNC_IN 上的一个脉冲触发效果相同</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;About ImuDesk</source>
        <translation>关于 ImuDesk(&amp;A)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Compare &amp;devices</source>
        <translation>设备对比(&amp;D)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>One channel of every connected device on one time axis, live whichever tab is in front</source>
        <translation>所有已连接设备的同一通道绘于同一时间轴上，无论哪个标签页在前都实时更新</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;User guide</source>
        <translation>用户指南(&amp;U)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>How to connect, chart, configure, calibrate, update, record and test a tray</source>
        <translation>如何连接、绘图、配置、校准、升级、录制以及测试整盘模块</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Keyboard shortcuts</source>
        <translation>键盘快捷键(&amp;K)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Every key combination of this window, with what it does</source>
        <translation>本窗口的所有组合键及其功能</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Preferences…</source>
        <translation>首选项(&amp;P)…</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Layout: %1</source>
        <translation>布局：%1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Charts, the values table and the 3D attitude</source>
        <translation>图表、数值表和 3D 姿态</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The device&apos;s settings beside the charts</source>
        <translation>设备设置与图表并列</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A large 3D attitude view and the console</source>
        <translation>大尺寸 3D 姿态视图和控制台</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Charts, the values, the raw bytes and the command log</source>
        <translation>图表、数值、原始字节和命令日志</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Production station…</source>
        <translation>生产测试台(&amp;P)…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Test a tray of modules at once against a test plan: a verdict and a report per serial number</source>
        <translation>按测试计划同时测试一托盘模块：每个序列号一个判定结果和一份报告</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Live bridge…</source>
        <translation>实时桥接(&amp;L)…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Send the connected devices&apos; samples live to Foxglove, Lichtblick and PlotJuggler</source>
        <translation>将已连接设备的采样实时发送到 Foxglove、Lichtblick 和 PlotJuggler</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The live bridge is running: click to open its window</source>
        <translation>实时桥接正在运行：点击打开其窗口</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Results…</source>
        <translation>测试结果(&amp;R)…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Every module the station tested: search by serial number, each attempt&apos;s measurements, the yield and a measurement&apos;s trend with Cpk</source>
        <translation>测试台测试过的每个模块：按序列号搜索、每次尝试的测量项、良率，以及某一测量项的趋势和 Cpk</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Reset layout</source>
        <translation>重置布局(&amp;R)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Put every panel of this tab back where the chosen layout has it</source>
        <translation>将此标签页的所有面板放回所选布局中的位置</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Compare devices</source>
        <translation>设备对比</translation>
    </message>
    <message>
        <location line="-1"/>
        <source>Connection</source>
        <translation>连接</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::ModbusConnectDialog</name>
    <message>
        <location filename="../ui/bus/bus_connect_dialog.cpp" line="-207"/>
        <source>Connect over Modbus RTU</source>
        <translation>通过 Modbus RTU 连接</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The RS-485 adapter&apos;s serial port, or a simulated device</source>
        <translation>RS-485 适配器的串口，或模拟设备</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 (%2)</source>
        <translation>%1（%2）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Simulated HI14 (Modbus)</source>
        <translation>模拟 HI14（Modbus）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Simulated HEC495 (Modbus)</source>
        <translation>模拟 HEC495（Modbus）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Port:</source>
        <translation>串口(&amp;P)：</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>HiPNUC module</source>
        <translation>HiPNUC 模块</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>HEC495 compass</source>
        <translation>HEC495 罗盘</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Which register map the device has</source>
        <translation>设备使用的寄存器表</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Device:</source>
        <translation>设备(&amp;D)：</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Modbus node ID (slave address), 1 to 247; HiPNUC modules default to 80, the HEC495 to 1</source>
        <translation>Modbus 节点 ID（从站地址），1 至 247；HiPNUC 模块默认为 80，HEC495 默认为 1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Node ID:</source>
        <translation>节点 ID(&amp;N)：</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Baud rate of the RS-485 bus</source>
        <translation>RS-485 总线的波特率</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Baud rate:</source>
        <translation>波特率(&amp;B)：</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>None</source>
        <translation>无</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Even</source>
        <translation>偶校验</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Odd</source>
        <translation>奇校验</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>P&amp;arity:</source>
        <translation>校验位(&amp;A)：</translation>
    </message>
    <message>
        <location line="+4"/>
        <source> Hz</source>
        <translation> Hz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>How often the sensor registers are read; limited to what the baud rate carries</source>
        <translation>传感器寄存器的读取频率；受波特率所能承载的速率限制</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>P&amp;olling rate:</source>
        <translation>轮询频率(&amp;O)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Also read the ship-motion registers (heave)</source>
        <translation>同时读取船舶运动寄存器（垂荡）</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::ModbusScanDialog</name>
    <message>
        <location filename="../ui/bus/modbus_scan_dialog.cpp" line="+24"/>
        <source>Scan the Modbus bus</source>
        <translation>扫描 Modbus 总线</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Every baud rate (4800 to 921600)</source>
        <translation>所有波特率（4800 至 921600）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>First node ID</source>
        <translation>起始节点 ID</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Last node ID</source>
        <translation>结束节点 ID</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Node ID</source>
        <translation>节点 ID</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Baud</source>
        <translation>波特率</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Device</source>
        <translation>设备</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Start</source>
        <translation>开始</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cancel scan</source>
        <translation>取消扫描</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Use</source>
        <translation>使用</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Close</source>
        <translation>关闭</translation>
    </message>
    <message>
        <location line="+60"/>
        <source>The first node ID must not be above the last.</source>
        <translation>起始节点 ID 不能大于结束节点 ID。</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Scanning ...</source>
        <translation>正在扫描...</translation>
    </message>
    <message numerus="yes">
        <location line="+28"/>
        <source>Cancelled; %n device(s) found so far.</source>
        <translation>
            <numerusform>已取消；目前找到 %n 台设备。</numerusform>
        </translation>
    </message>
    <message>
        <location line="+2"/>
        <source>No device answered. Check the wiring (A/B), the baud rate and parity, or scan every baud rate.</source>
        <translation>没有设备应答。请检查接线（A/B）、波特率和校验位，或扫描所有波特率。</translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>%n device(s) found.</source>
        <translation>
            <numerusform>找到 %n 台设备。</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>imudesk::ui::ModuleHistoryView</name>
    <message>
        <location filename="../ui/results/module_history_view.cpp" line="+125"/>
        <source>Attempt, step, measurement</source>
        <translation>尝试、步骤、测量项</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Value</source>
        <translation>数值</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Unit</source>
        <translation>单位</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Limits</source>
        <translation>限值</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Marginal band</source>
        <translation>临界区间</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Outcome</source>
        <translation>结果</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A pass whose value lies beyond this band, but inside its limits, is marked marginal</source>
        <translation>数值超出此范围但仍在限值内的通过结果标记为临界</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Attempt</source>
        <translation>尝试次数</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Kind</source>
        <translation>类型</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>File</source>
        <translation>文件</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Files:</source>
        <translation>文件：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Details:</source>
        <translation>详细信息：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Select an attempt, a step or a measurement to read all of it here.</source>
        <translation>选择一次尝试、一个步骤或一项测量，在此阅读其全部内容。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Open</source>
        <translation>打开</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Open the chosen file (the PDF report, the evidence recording) in the desktop&apos;s application for it</source>
        <translation>用桌面上的相应程序打开所选文件（PDF 报告、证据录制文件）</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Select a module above to see every attempt of its serial number.</source>
        <translation>在上方选择一个模块，即可查看该序列号的每一次尝试。</translation>
    </message>
    <message numerus="yes">
        <location line="+4"/>
        <source>History of %1: %n attempt(s)</source>
        <translation>
            <numerusform>%1 的历史：%n 次尝试</numerusform>
        </translation>
    </message>
    <message>
        <location line="+36"/>
        <source>Attempt %1 · %2</source>
        <translation>第 %1 次尝试 · %2</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Plan: %1
Station: %2 · slot %3 · operator %4
Product: %5 · firmware %6
Finished: %7
Record: %8</source>
        <translation>测试计划：%1
测试台：%2 · 工位 %3 · 操作员 %4
产品：%5 · 固件 %6
结束：%7
记录：%8</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>skipped</source>
        <translation>已跳过</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>for information</source>
        <translation>仅供参考</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The value&apos;s magnitude is compared with the limit</source>
        <translation>以数值的绝对值与限值比较</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 = %2 %3</source>
        <translation>%1 = %2 %3</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Limits: %1</source>
        <translation>限值：%1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Marginal band: %1</source>
        <translation>临界区间：%1</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>PDF report</source>
        <translation>PDF 报告</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Recording</source>
        <translation>录制文件</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1
SHA-256: %2</source>
        <translation>%1
SHA-256：%2</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::ModuleTableModel</name>
    <message>
        <location filename="../ui/results/module_table_model.cpp" line="+108"/>
        <source>Started</source>
        <translation>开始时间</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Serial number</source>
        <translation>序列号</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Outcome</source>
        <translation>结果</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Plan</source>
        <translation>测试计划</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Station</source>
        <translation>测试台</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Slot</source>
        <translation>工位</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Product</source>
        <translation>产品</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Firmware</source>
        <translation>固件</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Attempt</source>
        <translation>尝试次数</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::MountingPicker</name>
    <message>
        <location filename="../ui/configuration/mounting_picker.cpp" line="+34"/>
        <source>Mounting (URFR)</source>
        <translation>安装方式（URFR）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Where do the module&apos;s axes point on the body (right, forward, up)? Pick a picture, a code, or the directions of IMU X and IMU Y. The setting takes effect after SAVECONFIG and a reset.</source>
        <translation>模块各轴在载体上指向何方（右、前、上）？请选择图示或代码，或指定 IMU X 和 IMU Y 的指向。设置在 SAVECONFIG 并复位后生效。</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Code:</source>
        <translation>代码：</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>IMU X points:</source>
        <translation>IMU X 指向：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>IMU Y points:</source>
        <translation>IMU Y 指向：</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>IMU Z points:</source>
        <translation>IMU Z 指向：</translation>
    </message>
    <message>
        <location line="+89"/>
        <source>(no right-handed mounting)</source>
        <translation>（无法构成右手系的安装方式）</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Command: %1</source>
        <translation>指令：%1</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::PdfOutput</name>
    <message>
        <location filename="../ui/reports/pdf_output.cpp" line="+21"/>
        <source>No file name was given for the report.</source>
        <translation>未指定报告的文件名。</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>The report could not be rendered as PDF.</source>
        <translation>无法将报告生成为 PDF。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Cannot write the report to %1: %2. Choose another folder.</source>
        <translation>无法将报告写入 %1：%2。请选择其他文件夹。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Cannot write the report to %1: %2. Check the free disk space and try again.</source>
        <translation>无法将报告写入 %1：%2。请检查磁盘剩余空间后重试。</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::PlanEditorDialog</name>
    <message>
        <location filename="../ui/station/plan_editor_dialog.cpp" line="+199"/>
        <source>Plan &amp;name:</source>
        <translation>计划名称(&amp;N)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Shown in the station window, the reports and the run folder&apos;s name</source>
        <translation>显示在生产测试台窗口、报告和运行文件夹名称中</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Steps, in the order they run (unchecked: reported as skipped):</source>
        <translation>按运行顺序排列的步骤（未勾选的记为已跳过）(&amp;S)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Up</source>
        <translation>上移</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Move the step up (Ctrl+Up)</source>
        <translation>上移该步骤（Ctrl+Up）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Down</source>
        <translation>下移</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Move the step down (Ctrl+Down)</source>
        <translation>将步骤下移（Ctrl+Down）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Add</source>
        <translation>添加</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Add a step after the selected one</source>
        <translation>在所选步骤之后添加步骤</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Remove</source>
        <translation>移除</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Remove the selected step (Delete)</source>
        <translation>移除所选步骤（Delete）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save</source>
        <translation>保存</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Write the plan to its file (Ctrl+S)</source>
        <translation>将测试计划写入其文件（Ctrl+S）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save as…</source>
        <translation>另存为…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Write the plan to another file; paths to its files follow it</source>
        <translation>将测试计划写入另一个文件；其引用的文件路径随之调整</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>The plan has changes that are not saved.</source>
        <translation>测试计划有未保存的更改。</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>%1. %2</source>
        <translation>%1. %2</translation>
    </message>
    <message>
        <location line="+52"/>
        <source>No step selected</source>
        <translation>未选择步骤</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Choose a step in the list to edit its limits, or add one.</source>
        <translation>在列表中选择一个步骤以编辑其限值，或添加一个步骤。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Step %1: %2</source>
        <translation>步骤 %1：%2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 This step is off: the reports list it as skipped.</source>
        <translation>%1 此步骤已禁用：报告中将其列为已跳过。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>This step has no parameters.</source>
        <translation>此步骤没有参数。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1:</source>
        <translation>%1：</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>%1
From %2%4 to %3%4; default %5%4.</source>
        <translation>%1
范围 %2%4 至 %3%4；默认 %5%4。</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>Marginal band</source>
        <translation>临界区间</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Mark values close to the limit: they still pass, and the results say they were marginal</source>
        <translation>标记接近限值的数值：它们仍判为通过，但结果中注明为临界</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Values above this, up to the limit, pass marked marginal.
From %1%3 to %2%3, below the limit.</source>
        <translation>高于此值且不超过限值的数值判为通过，并标记为临界。
范围 %1%3 至 %2%3，须低于限值。</translation>
    </message>
    <message>
        <location line="+46"/>
        <source>&quot;%1&quot; needs a number from %2 to %3</source>
        <translation>“%1”需要 %2 至 %3 之间的数值</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>step %1 (%2): %3</source>
        <translation>步骤 %1（%2）：%3</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>%1
Default: %2</source>
        <translation>%1
默认：%2</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Browse…</source>
        <translation>浏览…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Choose the file; inside the plan&apos;s folder it is kept relative to it</source>
        <translation>选择文件；位于测试计划所在文件夹内的文件以相对路径保存</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>Firmware images (*.hex *.ihex *.bin);;All files (*)</source>
        <translation>固件镜像 (*.hex *.ihex *.bin);;所有文件 (*)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Configuration profiles (*.json);;All files (*)</source>
        <translation>配置方案 (*.json);;所有文件 (*)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Choose a file for &quot;%1&quot;</source>
        <translation>为“%1”选择文件</translation>
    </message>
    <message>
        <location line="+63"/>
        <source>The plan can run.</source>
        <translation>测试计划可以运行。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The plan cannot run yet:</source>
        <translation>测试计划暂时无法运行：</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>(no name)</source>
        <translation>（未命名）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not saved</source>
        <translation>未保存</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Test plan – %1 (%2)%3</source>
        <translation>测试计划 – %1（%2）%3</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>Save test plan</source>
        <translation>保存测试计划</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Station plans (*.json)</source>
        <translation>测试计划 (*.json)</translation>
    </message>
    <message>
        <location line="+43"/>
        <source>Test plan</source>
        <translation>测试计划</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::PoseTiles</name>
    <message>
        <location filename="../ui/calibration/verify_module_wizard.cpp" line="+73"/>
        <source>%1 up</source>
        <translation>%1 朝上</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::PreferencesDialog</name>
    <message>
        <location filename="../ui/workspace/preferences_dialog.cpp" line="+23"/>
        <source>Preferences</source>
        <translation>首选项</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Language</source>
        <translation>语言</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>System language</source>
        <translation>跟随系统</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The language of the user interface. Takes effect the next time ImuDesk starts.</source>
        <translation>用户界面的语言。下次启动 ImuDesk 时生效。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Language:</source>
        <translation>语言(&amp;L)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The new language is used after a restart.</source>
        <translation>新语言在重新启动后生效。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Display</source>
        <translation>显示</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>G (1 G = 9.8 m/s²)</source>
        <translation>G（1 G = 9.8 m/s²）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>m/s²</source>
        <translation>m/s²</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Unit of the accelerometer values and chart. Recorded data keeps the device&apos;s unit (G).</source>
        <translation>加速度计数值和曲线的单位。记录的数据保持设备的单位（G）。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Acceleration:</source>
        <translation>加速度(&amp;A)：</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>deg/s</source>
        <translation>deg/s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>rad/s</source>
        <translation>rad/s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Unit of the gyroscope values and chart. Recorded data keeps the device&apos;s unit (deg/s).</source>
        <translation>陀螺仪数值和曲线的单位。记录的数据保持设备的单位（deg/s）。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Angular &amp;rate:</source>
        <translation>角速度(&amp;R)：</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>ENU (east, north, up)</source>
        <translation>ENU（东、北、天）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>NED (north, east, down)</source>
        <translation>NED（北、东、地）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>World frame of the 3D attitude view.</source>
        <translation>三维姿态视图的世界坐标系。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Attitude &amp;frame:</source>
        <translation>姿态坐标系(&amp;F)：</translation>
    </message>
    <message>
        <location line="+3"/>
        <source> Hz</source>
        <translation> Hz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>How often charts and values are redrawn (%1 to %2 Hz). Lower rates use less CPU.</source>
        <translation>曲线和数值的刷新频率（%1 至 %2 Hz）。频率越低占用 CPU 越少。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Chart &amp;refresh:</source>
        <translation>曲线刷新(&amp;R)：</translation>
    </message>
    <message>
        <location line="+3"/>
        <source> min</source>
        <translation> 分钟</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The longest time window a chart can show (%1 to %2 minutes).</source>
        <translation>曲线可显示的最长时间窗口（%1 至 %2 分钟）。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Chart &amp;history:</source>
        <translation>曲线历史(&amp;H)：</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Recording</source>
        <translation>记录</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Documents folder</source>
        <translation>文档文件夹</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Where new recordings are written.</source>
        <translation>新记录保存的位置。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Browse…</source>
        <translation>浏览(&amp;B)…</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Folder:</source>
        <translation>文件夹(&amp;F)：</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>File name of a new recording. {product}, {serial}, {date} and {time} are replaced.</source>
        <translation>新记录的文件名。{product}、{serial}、{date} 和 {time} 会被替换。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>File &amp;pattern:</source>
        <translation>文件名模式(&amp;P)：</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Example:</source>
        <translation>示例：</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Connection</source>
        <translation>连接</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Reconnect by itself when an unplugged device comes back</source>
        <translation>拔出的设备重新插入时自动重连(&amp;R)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>After a cable is pulled, wait for the same device (USB serial number, else port) and reconnect at the last baud rate.</source>
        <translation>线缆拔出后，等待同一设备（按 USB 序列号，否则按端口）重新出现，并以上次的波特率重新连接。</translation>
    </message>
    <message>
        <location line="+59"/>
        <source>Recording folder</source>
        <translation>记录文件夹</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::ProfileDialog</name>
    <message>
        <location filename="../ui/configuration/profile_dialog.cpp" line="+21"/>
        <source>Configuration profiles</source>
        <translation>配置方案</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Read device</source>
        <translation>读取设备</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save device to profile…</source>
        <translation>将设备配置保存为方案…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Load profile…</source>
        <translation>加载方案…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Apply to this device</source>
        <translation>应用到此设备</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Setting</source>
        <translation>设置项</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Profile</source>
        <translation>方案</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Device</source>
        <translation>设备</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Note</source>
        <translation>备注</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Other ports (comma-separated):</source>
        <translation>其他串口（以逗号分隔）：</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Apply and save to each</source>
        <translation>逐个应用并保存</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Port</source>
        <translation>串口</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Serial number</source>
        <translation>序列号</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Product</source>
        <translation>产品</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Result</source>
        <translation>结果</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Details</source>
        <translation>详情</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>%1 settings applied and verified.</source>
        <translation>已应用并验证 %1 项设置。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 of %2 settings verified. %3</source>
        <translation>已验证 %1 / %2 项设置。%3</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>read the device first</source>
        <translation>请先读取设备</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Saved %1 settings to %2.</source>
        <translation>已将 %1 项设置保存到 %2。</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Loaded %1 (%2 settings, taken from %3 %4).</source>
        <translation>已加载 %1（%2 项设置，取自 %3 %4）。</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>The device already matches the profile.</source>
        <translation>设备已与方案一致。</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>OK (%1 changed)</source>
        <translation>OK（更改 %1 项）</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>FAILED</source>
        <translation>失败</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Save profile</source>
        <translation>保存方案</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+8"/>
        <source>ImuDesk profiles (*.json)</source>
        <translation>ImuDesk 方案 (*.json)</translation>
    </message>
    <message>
        <location line="-1"/>
        <source>Load profile</source>
        <translation>加载方案</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::RawBytesView</name>
    <message numerus="yes">
        <location filename="../ui/workspace/raw_bytes_view.cpp" line="+196"/>
        <source>… %n read(s) or write(s) not shown (the log dropped them before this view caught up) …</source>
        <translation>
            <numerusform>… 有 %n 次读取或写入未显示（在此视图跟上之前，日志已将其丢弃）…</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+3"/>
        <source>… %n byte(s) not shown (more arrived than the view holds) …</source>
        <translation>
            <numerusform>… 有 %n 字节未显示（到达的数据超出视图容量）…</numerusform>
        </translation>
    </message>
    <message>
        <location line="+64"/>
        <source>Pause</source>
        <translation>暂停</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stop updating the view; the bytes are still recorded</source>
        <translation>停止更新视图；字节仍会继续记录</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Clear</source>
        <translation>清空</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Empty the view</source>
        <translation>清空视图</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Copy</source>
        <translation>复制</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Copy the selected lines, or everything shown, to the clipboard</source>
        <translation>将所选行（未选择时为全部显示内容）复制到剪贴板</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Link traffic: time (s), direction (RX from the device, TX to it), byte offset, hex and ASCII</source>
        <translation>链路流量：时间（s）、方向（RX 为来自设备，TX 为发往设备）、字节偏移、十六进制和 ASCII</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>RX %1 bytes, TX %2 bytes</source>
        <translation>RX %1 字节，TX %2 字节</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Paused — %1</source>
        <translation>已暂停 — %1</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::RecordingControls</name>
    <message>
        <location filename="../ui/recording/recording_controls.cpp" line="+22"/>
        <source>Record</source>
        <translation>记录</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Stop</source>
        <translation>停止</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Folder the capture files are written to</source>
        <translation>记录文件的保存文件夹</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>File name; {date}, {time}, {product} and {serial} are filled in. Ending in .imucap: every byte, to replay and export later; ending in .mcap: the decoded samples as MCAP, which PlotJuggler, Foxglove and Lichtblick open</source>
        <translation>文件名；{date}、{time}、{product} 和 {serial} 会自动填入。以 .imucap 结尾：记录每个字节，便于之后回放和导出；以 .mcap 结尾：以 MCAP 记录解码后的采样，可由 PlotJuggler、Foxglove 和 Lichtblick 打开</translation>
    </message>
    <message>
        <location line="+6"/>
        <source> s</source>
        <translation> 秒</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>until Stop</source>
        <translation>直到按下停止</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stop the recording by itself after this many seconds (0: until you press Stop)</source>
        <translation>录制到这么多秒后自动停止（0：直到按下“停止”）</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>Folder:</source>
        <translation>文件夹：</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>File:</source>
        <translation>文件：</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Stop after:</source>
        <translation>自动停止：</translation>
    </message>
    <message>
        <location line="+111"/>
        <source>Not recording: the device is not connected. Press Connect (Ctrl+K), then Record (Ctrl+R).</source>
        <translation>未在录制：设备未连接。请按“连接”(Ctrl+K)，再按“录制”(Ctrl+R)。</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>The folder %1 does not exist. Choose another one.</source>
        <translation>文件夹 %1 不存在。请另选一个文件夹。</translation>
    </message>
    <message>
        <location line="+47"/>
        <source>Recording to %1</source>
        <translation>正在记录到 %1</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Saved %1 (stopped after %2 s, as set)</source>
        <translation>已保存 %1（按设定在 %2 秒后停止）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Saved %1</source>
        <translation>已保存 %1</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>%1:%2:%3</source>
        <translation>%1:%2:%3</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1 B</source>
        <translation>%1 字节</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 KiB</source>
        <translation>%1 KiB</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 MiB</source>
        <translation>%1 MiB</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 GiB</source>
        <translation>%1 GiB</translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>%n frame(s)</source>
        <translation>
            <numerusform>%n 帧</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>imudesk::ui::RegisterBrowser</name>
    <message>
        <location filename="../ui/bus/register_browser.cpp" line="+24"/>
        <source>Modbus registers</source>
        <translation>Modbus 寄存器</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>03 Read holding registers</source>
        <translation>03 读保持寄存器</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>06 Write single register</source>
        <translation>06 写单个寄存器</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Register address</source>
        <translation>寄存器地址</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Send</source>
        <translation>发送</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Address</source>
        <translation>地址</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>Writing %1 to register 0x%2 ...</source>
        <translation>正在将 %1 写入寄存器 0x%2 ...</translation>
    </message>
    <message>
        <location line="+90"/>
        <source>Not connected.</source>
        <translation>未连接。</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Only functions 03 and 06 are supported by these devices.</source>
        <translation>这些设备仅支持功能码 03 和 06。</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>count </source>
        <translation>数量 </translation>
    </message>
    <message>
        <location line="+3"/>
        <source>value </source>
        <translation>数值 </translation>
    </message>
</context>
<context>
    <name>imudesk::ui::ReplayControls</name>
    <message>
        <location filename="../ui/recording/replay_controls.cpp" line="+33"/>
        <location line="+83"/>
        <location line="+28"/>
        <source>Play</source>
        <translation>播放</translation>
    </message>
    <message>
        <location line="-106"/>
        <source>%1×</source>
        <translation>%1×</translation>
    </message>
    <message>
        <location line="+0"/>
        <location line="+64"/>
        <source>As fast as possible</source>
        <translation>尽可能快</translation>
    </message>
    <message>
        <location line="-59"/>
        <source>Loop</source>
        <translation>循环</translation>
    </message>
    <message>
        <location line="+61"/>
        <source>Session: all devices together</source>
        <translation>会话：所有设备同步</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>This capture is one device of a recorded session. Play, pause, seek, speed and loop act on every device of the session; the positions are times since the session started, so one position is the same instant in every tab.</source>
        <translation>此记录是已录制会话中的一台设备。播放、暂停、定位、速度和循环作用于会话中的每台设备；位置是自会话开始以来的时间，因此同一位置在每个标签页中都是同一时刻。</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>This file is a raw byte dump: it has no arrival times, so the times come from the device&apos;s own clock (HI91/HI83 time stamps or NMEA UTC time).</source>
        <translation>此文件是原始字节转储：没有接收时间，因此时间取自设备自身的时钟（HI91/HI83 时间戳或 NMEA UTC 时间）。</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Pause</source>
        <translation>暂停</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1 / %2 (device clock)</source>
        <translation>%1 / %2（设备时钟）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 / %2</source>
        <translation>%1 / %2</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::ResultsFormat</name>
    <message>
        <location filename="../ui/results/results_format.cpp" line="+13"/>
        <source>PASS (marginal)</source>
        <translation>通过（临界）</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>PASS</source>
        <translation>通过</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>FAIL</source>
        <translation>失败</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>ERROR</source>
        <translation>错误</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>ABORTED</source>
        <translation>中止</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::ResultsWindow</name>
    <message>
        <location filename="../ui/results/results_window.cpp" line="+308"/>
        <source>Results</source>
        <translation>测试结果</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Database:</source>
        <translation>数据库：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Open…</source>
        <translation>打开…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Read another results file (an SQLite file a station wrote: results.sqlite)</source>
        <translation>读取另一个结果文件（测试台写入的 SQLite 文件：results.sqlite）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Serial:</source>
        <translation>序列号：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>part of a serial number</source>
        <translation>序列号的一部分</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Modules whose serial number contains this text, as it is written</source>
        <translation>序列号中包含此文本（按原样匹配）的模块</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Plan:</source>
        <translation>测试计划：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Station:</source>
        <translation>测试台：</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Any</source>
        <translation>全部</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>From</source>
        <translation>从</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Only modules started on this day or later (also for the yield and the trend)</source>
        <translation>仅包括在此日期或之后开始的模块（良率和趋势也按此筛选）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>To</source>
        <translation>至</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Only modules started on this day or earlier (also for the trend)</source>
        <translation>仅包括在此日期或之前开始的模块（趋势也按此筛选）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Search</source>
        <translation>搜索</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>List the modules that match the filter, and count the yield of its plan (Enter)</source>
        <translation>列出符合筛选条件的模块，并统计其测试计划的良率 (Enter)</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+95"/>
        <source>Reading the results database…</source>
        <translation>正在读取结果数据库…</translation>
    </message>
    <message>
        <location line="-94"/>
        <source>Modules</source>
        <translation>模块</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The modules found; select one to see every attempt of its serial number</source>
        <translation>找到的模块；选择一个即可查看该序列号的每一次尝试</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Yield</source>
        <translation>良率</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Pass, fail and yield of the chosen plan, per firmware and fixture slot</source>
        <translation>所选测试计划的通过数、失败数和良率，按固件和夹具工位统计</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Trend</source>
        <translation>趋势</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>One measurement of the chosen plan over time, with its limits and Cpk</source>
        <translation>所选测试计划中某一测量项随时间的变化，含限值和 Cpk</translation>
    </message>
    <message>
        <location line="+5"/>
        <location line="+242"/>
        <source>Choose a plan in the filter above: the yield is counted per plan.</source>
        <translation>请在上方筛选栏中选择测试计划：良率按测试计划统计。</translation>
    </message>
    <message>
        <location line="-241"/>
        <location line="+261"/>
        <source>Choose a plan in the filter above to see its measurements over time.</source>
        <translation>请在上方筛选栏中选择测试计划，以查看其测量项随时间的变化。</translation>
    </message>
    <message>
        <location line="-215"/>
        <source>Open a results database</source>
        <translation>打开结果数据库</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Results databases (*.sqlite *.db);;All files (*)</source>
        <translation>结果数据库 (*.sqlite *.db);;所有文件 (*)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>none</source>
        <translation>无</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the line database, %1</source>
        <translation>产线数据库，%1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the file %1</source>
        <translation>文件 %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>this station&apos;s database, %1</source>
        <translation>本测试台的数据库，%1</translation>
    </message>
    <message numerus="yes">
        <location line="+24"/>
        <source>The newest %n module(s) found; there are more: narrow the filter to see them.</source>
        <translation>
            <numerusform>显示最新的 %n 个模块；还有更多：请缩小筛选范围以查看。</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+3"/>
        <source>%n module(s) found.</source>
        <translation>
            <numerusform>找到 %n 个模块。</numerusform>
        </translation>
    </message>
    <message>
        <location line="+14"/>
        <source>The line database %1 could not be read: %2
Check the network and that the server runs, then press Search to try again; or read this station&apos;s own file with Open….</source>
        <translation>无法读取产线数据库 %1：%2
请检查网络以及服务器是否在运行，然后按“搜索”重试；或用“打开…”读取本测试台自己的文件。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 could not be read: %2
Is it a results database that ImuDesk wrote? Choose another file with Open….</source>
        <translation>无法读取 %1：%2
它是 ImuDesk 写入的结果数据库吗？请用“打开…”选择其他文件。</translation>
    </message>
    <message>
        <location line="+72"/>
        <source>There are no results in %1 yet: the station writes this file with its first run. Open another file with Open…, or set the line database in the station window.</source>
        <translation>%1 中还没有结果：测试台在第一次运行时才会写入此文件。请用“打开…”打开其他文件，或在测试台窗口中设置产线数据库。</translation>
    </message>
    <message>
        <location line="+43"/>
        <source>Reading the history of %1…</source>
        <translation>正在读取 %1 的历史…</translation>
    </message>
    <message>
        <location line="+58"/>
        <source>The plan&apos;s modules have no measurements here.</source>
        <translation>此测试计划的模块在这里没有测量项。</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>%1 is not on this computer (it may be on the station that tested the module, or moved). Look for it in that station&apos;s report folder or in the shared artifact folder.</source>
        <translation>%1 不在这台计算机上（可能在测试该模块的测试台上，或已被移动）。请在该测试台的报告文件夹或共享附件文件夹中查找。</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1 could not be opened: no application on this computer opens it. Open it from the file manager instead.</source>
        <translation>无法打开 %1：这台计算机上没有能打开它的程序。请改从文件管理器中打开。</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::RotationGuide</name>
    <message>
        <location filename="../ui/calibration/rotation_guide.cpp" line="+119"/>
        <source>Turn the module at least one full turn about each of its axes, slowly (20-100 deg/s), in any order</source>
        <translation>绕模块的每根轴至少转一整圈，缓慢转动（20-100 deg/s），顺序不限</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>About X: roll it over</source>
        <translation>绕 X 轴：侧向翻滚</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>About Y: tip it end over end</source>
        <translation>绕 Y 轴：首尾翻转</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>About Z: turn it flat, like a compass</source>
        <translation>绕 Z 轴：平放旋转，像指南针一样</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::SessionRecordingWindow</name>
    <message>
        <location filename="../ui/recording/session_recording_window.cpp" line="+41"/>
        <source>Folder for the session</source>
        <translation>会话存放文件夹</translation>
    </message>
    <message>
        <location line="+49"/>
        <source>Exported the aligned session to %1.</source>
        <translation>已将对齐后的会话导出到 %1。</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>Record all devices</source>
        <translation>录制所有设备</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Records every connected device into one session folder: each device&apos;s capture and session.json with their clocks. Replays and exports put the devices on one time base.</source>
        <translation>将所有已连接的设备录制到同一个会话文件夹：包括每台设备的采集文件，以及记录各设备时钟的 session.json。回放和导出时，所有设备使用同一时间基准。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Into:</source>
        <translation>保存到：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A new folder session-&lt;date&gt;-&lt;time&gt; is made here for each session</source>
        <translation>每次会话都会在此新建一个 session-&lt;date&gt;-&lt;time&gt; 文件夹</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Choose…</source>
        <translation>选择…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Start</source>
        <translation>开始(&amp;S)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Start recording every connected device</source>
        <translation>开始录制所有已连接的设备</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>S&amp;top</source>
        <translation>停止(&amp;T)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Export aligned…</source>
        <translation>导出对齐数据(&amp;E)…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The last session as one tidy CSV, every device&apos;s samples in the order of the common time</source>
        <translation>将最近一次会话导出为一个整洁 CSV，所有设备的样本按公共时间排序</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>T&amp;wist to align…</source>
        <translation>扭转对齐(&amp;W)…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Find each device&apos;s constant offset from sharp turns of a shared fixture</source>
        <translation>根据共用工装的急速转动，求出每台设备的固定时间偏移</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Device</source>
        <translation>设备</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Link</source>
        <translation>链路</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Bytes</source>
        <translation>字节数</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Frames</source>
        <translation>帧数</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>State</source>
        <translation>状态</translation>
    </message>
    <message>
        <location line="+46"/>
        <source>No connected device can be recorded: connect the devices in their tabs first.</source>
        <translation>没有可录制的已连接设备：请先在各设备的标签页中连接设备。</translation>
    </message>
    <message numerus="yes">
        <location line="+17"/>
        <source>Recording %n device(s) into %1…</source>
        <translation>
            <numerusform>正在将 %n 台设备录制到 %1…</numerusform>
        </translation>
    </message>
    <message>
        <location line="+34"/>
        <source>recording</source>
        <translation>录制中</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>dropped out: %1</source>
        <translation>已掉线：%1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>back after a drop-out, recording</source>
        <translation>掉线后已恢复，录制中</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>stopped: %1</source>
        <translation>已停止：%1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>dropped out (marked in the session)</source>
        <translation>已掉线（已在会话中标记）</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>complete</source>
        <translation>已完成</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Recording for %1 s into %2</source>
        <translation>正在录制到 %2，已录制 %1 s</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Session recorded in %1.</source>
        <translation>会话已录制到 %1。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The recordings stopped, but the session&apos;s manifest could not be written: %1. The captures are in %2.</source>
        <translation>录制已停止，但无法写入会话清单文件：%1。采集文件位于 %2。</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Exporting the session…</source>
        <translation>正在导出会话…</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::SettingValueDelegate</name>
    <message>
        <location filename="../ui/configuration/setting_value_delegate.cpp" line="+83"/>
        <source>the value was refused</source>
        <translation>该值被拒绝</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::ShortcutsDialog</name>
    <message>
        <location filename="../ui/workspace/help_dialogs.cpp" line="+233"/>
        <source>Keyboard shortcuts</source>
        <translation>键盘快捷键</translation>
    </message>
    <message>
        <location line="+9"/>
        <source> or </source>
        <translation> 或 </translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Action</source>
        <translation>操作</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Keys</source>
        <translation>按键</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::StationModel</name>
    <message>
        <location filename="../ui/station/station_model.cpp" line="+79"/>
        <source>waiting to start</source>
        <translation>等待开始</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>connecting…</source>
        <translation>正在连接…</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>failed: %1</source>
        <translation>失败：%1</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>failed</source>
        <translation>失败</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>every step passed</source>
        <translation>所有步骤均通过</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not tested</source>
        <translation>未测试</translation>
    </message>
    <message>
        <location line="+8"/>
        <location line="+10"/>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <location line="-8"/>
        <source>Serial %1 · %2 · firmware %3</source>
        <translation>序列号 %1 · %2 · 固件 %3</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+1"/>
        <source>(none)</source>
        <translation>（无）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Firmware after the update: %1</source>
        <translation>更新后的固件：%1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source> (%1)</source>
        <translation>（%1）</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>    %1 = %2</source>
        <translation>    %1 = %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>    %1 = %2 (limit %3)%4</source>
        <translation>    %1 = %2（限值 %3）%4</translation>
    </message>
    <message>
        <location line="+2"/>
        <source> ✗</source>
        <translation> ✗</translation>
    </message>
    <message>
        <location line="+0"/>
        <source> (marginal)</source>
        <translation>（临界）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Report: %1</source>
        <translation>报告：%1</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1 (marginal)</source>
        <translation>%1（临界）</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::StationReport</name>
    <message>
        <location filename="../ui/reports/station_report.cpp" line="+31"/>
        <source>unknown</source>
        <translation>未知</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>ImuDesk station report: %1</source>
        <translation>ImuDesk 生产测试报告：%1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Device</source>
        <translation>设备</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Serial number</source>
        <translation>序列号</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Firmware</source>
        <translation>固件</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1, updated to %2</source>
        <translation>%1，已更新为 %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Port</source>
        <translation>串口</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Plan</source>
        <translation>测试计划</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>(unnamed)</source>
        <translation>（未命名）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Attempt</source>
        <translation>尝试次数</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Started (UTC)</source>
        <translation>开始时间（UTC）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Finished (UTC)</source>
        <translation>结束时间（UTC）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Verdict:</source>
        <translation>结论：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 (marginal)</source>
        <translation>%1（临界）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Failed at %1</source>
        <translation>失败步骤：%1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Steps</source>
        <translation>步骤</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Value</source>
        <translation>项目</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Measured</source>
        <translation>测量值</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Limit</source>
        <translation>限值</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Result</source>
        <translation>结果</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>within</source>
        <translation>在限值内</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>outside</source>
        <translation>超出限值</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>marginal</source>
        <translation>临界</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Evidence recording: %1</source>
        <translation>证据记录：%1</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>ImuDesk station report</source>
        <translation>ImuDesk 生产测试报告</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::StationTile</name>
    <message>
        <location filename="../ui/station/station_tiles.cpp" line="+103"/>
        <source>%1 → %2</source>
        <translation>%1 → %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>not identified yet</source>
        <translation>尚未识别</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>SN %1 · %2 · %3</source>
        <translation>序列号 %1 · %2 · %3</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>(none)</source>
        <translation>（无）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>(no product)</source>
        <translation>（无型号）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>(no firmware)</source>
        <translation>（无固件版本）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 % of the plan, each step weighted by how long it takes</source>
        <translation>已完成测试计划的 %1 %（各步骤按耗时加权）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Report</source>
        <translation>报告</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Open this module&apos;s PDF report: %1</source>
        <translation>打开此模块的 PDF 报告：%1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Report of %1</source>
        <translation>%1 的报告</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::StationView</name>
    <message>
        <location filename="../ui/station/station_view.cpp" line="+252"/>
        <location line="+77"/>
        <source>Production station</source>
        <translation>生产测试台</translation>
    </message>
    <message>
        <location line="-76"/>
        <source>Plan:</source>
        <translation>测试计划：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Open…</source>
        <translation>打开…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Open a test plan (a .json file saved by the plan editor)</source>
        <translation>打开测试计划（由计划编辑器保存的 .json 文件）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Edit…</source>
        <translation>编辑…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Edit the plan&apos;s steps and limits; the next Start uses the saved plan</source>
        <translation>编辑测试计划的步骤和限值；下次“开始”时使用已保存的计划</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>New from example</source>
        <translation>从示例新建</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A new plan from the example for HI14 modules, every step with its default limits, opened in the editor (without a firmware image; the profile step is off)</source>
        <translation>基于 HI14 模块示例新建测试计划，各步骤使用默认限值，并在编辑器中打开（不含固件镜像；配置方案步骤已禁用）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Ports:</source>
        <translation>串口：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The modules to test: check the port of each</source>
        <translation>要测试的模块：勾选每个模块的串口</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Refresh</source>
        <translation>刷新</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Look for serial ports again (after plugging in an adapter)</source>
        <translation>重新查找串口（插入适配器后使用）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Simulated tray…</source>
        <translation>模拟托盘…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Start simulated HI14 modules on pseudo-terminals, some of them with faults, to try the station without hardware</source>
        <translation>在伪终端上启动模拟 HI14 模块（部分带有故障），无需硬件即可试用生产测试台</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Reports:</source>
        <translation>报告：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Each run gets a folder here: the plan, summary.csv and summary.jsonl, a PDF report per module and the evidence recordings</source>
        <translation>每次运行都会在此处生成一个文件夹，内含：测试计划、summary.csv 和 summary.jsonl、每个模块的 PDF 报告以及证据记录</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Choose…</source>
        <translation>选择…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Choose the folder for the run folders</source>
        <translation>选择存放运行文件夹的文件夹</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Line database…</source>
        <translation>产线数据库…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Send every result to the line&apos;s PostgreSQL database too, and copy the reports to a shared folder</source>
        <translation>同时把每个结果发送到产线的 PostgreSQL 数据库，并把报告复制到共享文件夹</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Start</source>
        <translation>开始</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Run the plan on every checked port at once (Ctrl+R)</source>
        <translation>在所有已勾选的串口上同时运行测试计划（Ctrl+R）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stop every module&apos;s test; the running steps fail as cancelled (Esc)</source>
        <translation>停止所有模块的测试；运行中的步骤以“已取消”判为失败（Esc）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Re-run failed</source>
        <translation>重测失败模块</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Test the modules that failed again, into the same run folder as their next attempt (Ctrl+Shift+R)</source>
        <translation>重新测试失败的模块，结果作为下一次尝试存入同一运行文件夹（Ctrl+Shift+R）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Open run folder</source>
        <translation>打开运行文件夹</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Open the folder of this run: the PDF reports, summary.csv, summary.jsonl and the evidence recordings (Ctrl+Shift+O)</source>
        <translation>打开本次运行的文件夹：PDF 报告、summary.csv、summary.jsonl 和证据录制文件 (Ctrl+Shift+O)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Choose a plan and check the ports of the modules, then press Start (Ctrl+R). Each module gets a tile here; click a tile to open that module&apos;s workspace.</source>
        <translation>选择测试计划并勾选模块的串口，然后按“开始”（Ctrl+R）。每个模块在此处显示为一张卡片；点击卡片可打开该模块的工作区。</translation>
    </message>
    <message>
        <location line="+7"/>
        <location line="+149"/>
        <source>%1 (simulated)</source>
        <translation>%1（模拟）</translation>
    </message>
    <message>
        <location line="-87"/>
        <source>No plan yet: open one, or start from the example</source>
        <translation>尚无测试计划：请打开一个，或从示例新建</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>✓ %1</source>
        <translation>✓ %1</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>✗ %1 (off)</source>
        <translation>✗ %1（已禁用）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>not saved</source>
        <translation>未保存</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 · %2 of %3 steps · %4</source>
        <translation>%1 · 启用 %2/%3 个步骤 · %4</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>(no name)</source>
        <translation>（未命名）</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Open test plan</source>
        <translation>打开测试计划</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Station plans (*.json);;All files (*)</source>
        <translation>测试计划 (*.json);;所有文件 (*)</translation>
    </message>
    <message>
        <location line="+53"/>
        <source>Made by %1</source>
        <translation>制造商：%1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Adapter serial number %1</source>
        <translation>适配器序列号：%1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 (%2)</source>
        <translation>%1（%2）</translation>
    </message>
    <message>
        <location filename="../ui/station/station_view_tray.cpp" line="+37"/>
        <source>Simulated tray</source>
        <translation>模拟托盘</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Three with faults: a noisy gyro, a wrong mounting, firmware 1.6.6</source>
        <translation>其中三个带故障：陀螺仪噪声过大、安装方向错误、固件 1.6.6</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Simulated HI14 modules on pseudo-terminals, each on a rotation fixture (for the magnetometer calibration). They stop when this window closes.</source>
        <translation>运行在伪终端上的模拟 HI14 模块，每个都装在旋转工装上（用于地磁校准）。关闭此窗口时它们随之停止。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Modules:</source>
        <translation>模块数量：</translation>
    </message>
    <message>
        <location filename="../ui/station/station_view.cpp" line="+51"/>
        <source>Folder for the station&apos;s reports</source>
        <translation>生产测试台的报告文件夹</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>A report could not be written:
%1</source>
        <translation>无法写入报告：
%1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1 could not be opened: no application on this computer opens it. Open it from the file manager instead.</source>
        <translation>无法打开 %1：这台电脑上没有能打开它的应用程序。请改从文件管理器打开。</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>The report of %1 is written when its test has ended.</source>
        <translation>%1 的报告在其测试结束后写出。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 has no report: see the run folder&apos;s summary, or the message about the report.</source>
        <translation>%1 没有报告：请查看运行文件夹中的汇总，或关于报告的提示信息。</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>There is no run folder yet: press Start (Ctrl+R) first.</source>
        <translation>还没有运行文件夹：请先按“开始”(Ctrl+R)。</translation>
    </message>
    <message>
        <location line="+59"/>
        <source>Reports of this run: %1</source>
        <translation>本次运行的报告：%1</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::StatusFlagsWidget</name>
    <message>
        <location filename="../ui/workspace/status_flags_widget.cpp" line="+114"/>
        <source>Status:</source>
        <translation>状态：</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>good news when set</source>
        <translation>置位表示良好</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>information</source>
        <translation>信息</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>warning when set</source>
        <translation>置位表示警告</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&lt;b&gt;%1&lt;/b&gt; (bit %2, %3): %4&lt;br&gt;&lt;i&gt;Source: %5&lt;/i&gt;</source>
        <translation>&lt;b&gt;%1&lt;/b&gt;（第 %2 位，%3）：%4&lt;br&gt;&lt;i&gt;来源：%5&lt;/i&gt;</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>MAIN_STATUS flags of the latest frame. Set: amber = a warning about the data, blue = information, green = good news (magnetometer aiding the heading). Grey = clear; outlined = the frame carries no status word (firmware before 1.7.0, or another frame type)</source>
        <translation>最新帧的 MAIN_STATUS 标志。置位时：琥珀色 = 数据警告，蓝色 = 信息，绿色 = 良好（磁力计辅助航向）。灰色 = 未置位；仅边框 = 该帧不含状态字（1.7.0 之前的固件或其他帧类型）</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::ToolActions</name>
    <message>
        <location filename="../ui/workspace/tool_actions.cpp" line="+131"/>
        <source>&amp;Open capture…</source>
        <translation>打开记录(&amp;O)…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Play a recorded capture through the charts and views, as a live device (in a tab of its own when this one is connected); a recorded session&apos;s session.json opens every device, aligned</source>
        <translation>像实时设备一样在图表和视图中回放录制的捕获（当前标签页已连接时在新标签页中打开）；已录制会话的 session.json 会打开所有设备并对齐</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Import vendor CSV…</source>
        <translation>导入厂商 CSV(&amp;I)…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Turn a CSV written by the vendor&apos;s PC tool into a capture and play it</source>
        <translation>将厂商上位机软件生成的 CSV 转换为记录文件并回放</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Export capture…</source>
        <translation>导出记录文件(&amp;E)…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Write a capture as vendor CSV, tidy CSV or JSON Lines</source>
        <translation>将记录文件导出为厂商 CSV、整洁 CSV 或 JSONL</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Analyze capture…</source>
        <translation>分析记录文件(&amp;A)…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Statistics, output rate and jitter, lost frames and Allan deviation of a capture</source>
        <translation>记录文件的统计量、输出频率与抖动、丢帧及阿伦方差</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Find devices…</source>
        <translation>查找设备(&amp;F)…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>One sweep of every serial port and CAN bus: what is connected, at what rate and address, and two devices at one address</source>
        <translation>一次扫描所有串口和 CAN 总线：连接了哪些设备、速率和地址是多少，以及同一地址上的两台设备</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Connect over &amp;Modbus RTU…</source>
        <translation>通过 Modbus RTU 连接(&amp;M)…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Poll a module or compass on an RS-485 bus</source>
        <translation>轮询 RS-485 总线上的模块或罗盘</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Connect over C&amp;AN…</source>
        <translation>通过 CAN 连接(&amp;A)…</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Find the node IDs that answer on the bus</source>
        <translation>查找总线上有应答的节点 ID</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Con&amp;figuration</source>
        <translation>配置(&amp;F)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Every setting of the connected module: read, edit, apply, save</source>
        <translation>已连接模块的全部设置：读取、编辑、应用、保存</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Profiles…</source>
        <translation>配置方案(&amp;P)…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save the configuration to a file, compare a file with the device, apply it to several</source>
        <translation>将配置保存到文件、将文件与设备比对、批量应用到多台设备</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Output-rate &amp;calculator…</source>
        <translation>输出速率计算器(&amp;C)…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Bytes per second of the chosen outputs against the link&apos;s capacity</source>
        <translation>所选输出的每秒字节数与链路容量的对比</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Update firmware…</source>
        <translation>升级固件(&amp;U)…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Record</source>
        <translation>记录(&amp;R)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Record this device to a capture file; the recording panel shows the progress and Stop</source>
        <translation>将此设备录制到捕获文件；录制面板显示进度和“停止”按钮</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Record &amp;all devices…</source>
        <translation>录制所有设备(&amp;A)…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Record every connected tab into one session folder, the devices on one time base</source>
        <translation>将所有已连接的标签页录制到同一个会话文件夹，所有设备使用同一时间基准</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>T&amp;wist to align…</source>
        <translation>扭转对齐(&amp;W)…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Align the devices of a recorded session from sharp turns of the fixture they share</source>
        <translation>根据共用工装的急速转动，对齐已录制会话中的各设备</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Magnetometer…</source>
        <translation>磁力计(&amp;M)…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Calibrate the magnetometer: turn the module while the sphere fills, then judge the fit</source>
        <translation>地磁校准：转动模块直至球面填满，然后评估拟合结果</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Gyro scale factor…</source>
        <translation>陀螺仪标度因数(&amp;G)…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Turn the module a known angle about Z to correct the gyro&apos;s scale (CONFIG USRCAL)</source>
        <translation>绕 Z 轴将模块转动已知角度，以校正陀螺仪的标度因数（CONFIG USRCAL）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Attitude reset / level…</source>
        <translation>姿态复位/调平(&amp;A)…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Zero the heading or level the module (ATT RST), after checking that it is still</source>
        <translation>确认模块静止后，将航向角清零或调平模块（ATT RST）</translation>
    </message>
    <message>
        <location line="-22"/>
        <source>Listen to and configure a device on a CAN bus (J1939 or CANopen)</source>
        <translation>监听并配置 CAN 总线上的设备（J1939 或 CANopen）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Scan the bus…</source>
        <translation>扫描总线(&amp;S)…</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Write a new firmware image to the module over its serial port or its CAN bus, and verify it</source>
        <translation>通过串口或 CAN 总线向模块写入新固件并校验</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>&amp;Verify module…</source>
        <translation>验证模块(&amp;V)…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Is the module right? Turn it through still poses: its accelerometer, gyro and attitude judged, each figure with its bounds</source>
        <translation>模块是否正确？将它依次转到各个静止姿态：判定其加速度计、陀螺仪和姿态，每项数值都带有置信界限</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Compass calibration…</source>
        <translation>罗盘校准(&amp;C)…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The compass&apos;s own calibration methods, with the target poses to turn it to</source>
        <translation>罗盘自带的校准方法，并给出要转到的目标姿态</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Calibration &amp;history…</source>
        <translation>校准历史(&amp;H)…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Every finished calibration run per device: metrics, samples, PDF report</source>
        <translation>按设备查看每次完成的校准：指标、样本、PDF 报告</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Tools</source>
        <translation>工具(&amp;T)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Calibrate</source>
        <translation>校准(&amp;C)</translation>
    </message>
    <message>
        <location line="+67"/>
        <source>%1: its capture %2 is missing.</source>
        <translation>%1：其记录 %2 缺失。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 (%2): Modbus captures cannot be replayed yet; export the session to see its data.</source>
        <translation>%1（%2）：Modbus 记录尚不能回放；请导出会话以查看其数据。</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The session opened without some of its devices:</source>
        <translation>会话已打开，但缺少以下设备：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>No device of the session could be replayed:</source>
        <translation>会话中没有可回放的设备：</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1 could not be imported: %2</source>
        <translation>无法导入 %1：%2</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Open capture</source>
        <translation>打开记录文件</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+27"/>
        <source>Captures, sessions, vendor CSV and raw dumps (*.imucap session.json *.csv *.bin *.raw *.log *.dat *.txt);;All files (*)</source>
        <translation>记录、会话、厂商 CSV 和原始数据 (*.imucap session.json *.csv *.bin *.raw *.log *.dat *.txt);;所有文件 (*)</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Captures, vendor CSV and raw dumps (*.imucap *.csv *.bin *.raw *.log *.dat *.txt);;All files (*)</source>
        <translation>采集文件、厂商 CSV 和原始转储 (*.imucap *.csv *.bin *.raw *.log *.dat *.txt);;所有文件 (*)</translation>
    </message>
    <message>
        <location line="-31"/>
        <source>Import vendor CSV</source>
        <translation>导入厂商 CSV</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CSV files (*.csv);;All files (*)</source>
        <translation>CSV 文件 (*.csv);;所有文件 (*)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Save the imported capture as</source>
        <translation>将导入的记录文件另存为</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Captures (*.imucap)</source>
        <translation>记录文件 (*.imucap)</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Export capture</source>
        <translation>导出记录文件</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Analyze capture</source>
        <translation>分析记录文件</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::TrendView</name>
    <message>
        <location filename="../ui/results/trend_view.cpp" line="+113"/>
        <source>Measurement:</source>
        <translation>测量项：</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Pass</source>
        <translation>通过</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Fail</source>
        <translation>失败</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+1"/>
        <source>Limits</source>
        <translation>限值</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+1"/>
        <source>Marginal band</source>
        <translation>临界区间</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Module started</source>
        <translation>模块开始测试时间</translation>
    </message>
    <message>
        <location line="+145"/>
        <source>No values of this measurement in the time chosen.</source>
        <translation>所选时间内没有该测量项的数值。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>n = %1 · mean = %2 · σ = %3 · Cpk = %4</source>
        <translation>n = %1 · 均值 = %2 · σ = %3 · Cpk = %4</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Cpk, the process capability index: how far the mean lies from the nearer limit, in units of three standard deviations: min(USL − mean, mean − LSL) / 3σ, against the latest module&apos;s limits (%1). 1.33 or more is commonly asked for; below 1, some modules will fail. &quot;–&quot;: no limit, or no spread (fewer than two values, or all equal).</source>
        <translation>Cpk（过程能力指数）：均值距较近限值的距离，以三倍标准差为单位：min(USL − 均值, 均值 − LSL) / 3σ，按最新模块的限值（%1）计算。通常要求 1.33 以上；低于 1 时会有部分模块不合格。“–”：没有限值，或没有离散（少于两个数值，或全部相等）。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>none</source>
        <translation>无</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::TurnGauge</name>
    <message>
        <location filename="../ui/calibration/turn_gauge.cpp" line="+78"/>
        <source>%1° of %2°</source>
        <translation>%1° / %2°</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>lap %1 of %2 · %3 deg/s</source>
        <translation>第 %1 圈，共 %2 圈 · %3 deg/s</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::TwistAlignDialog</name>
    <message>
        <location filename="../ui/recording/twist_align_dialog.cpp" line="+27"/>
        <source>Twist to align</source>
        <translation>扭转对齐</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>For modules on one fixture. While every device records, turn the fixture sharply (faster than 60 deg/s) at least 3 times, at irregular intervals with a short rest between the turns, over at least 10 s. Then open the recorded session here: ImuDesk cross-correlates the devices&apos; gyro magnitudes and finds each device&apos;s constant time offset to the reference device.</source>
        <translation>适用于装在同一工装上的多个模块。在所有设备录制期间，急速转动工装（快于 60 deg/s）至少 3 次，间隔不规则，每两次转动之间短暂停顿，总时长至少 10 s。然后在此打开录制的会话：ImuDesk 对各设备的陀螺仪角速度模值做互相关，求出每台设备相对参考设备的固定时间偏移。</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>The folder of a recorded session: the one with session.json and a capture per device</source>
        <translation>已录制会话的文件夹：其中有 session.json，以及每台设备各一个采集文件</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Choose…</source>
        <translation>选择…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Open another recorded session</source>
        <translation>打开另一个已录制的会话</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The device the others are aligned to: its offset is 0</source>
        <translation>其他设备以此设备为基准对齐：其偏移为 0</translation>
    </message>
    <message>
        <location line="+5"/>
        <location line="+6"/>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <location line="-5"/>
        <source>Start of the twists, in seconds since the recording began (0: from the start)</source>
        <translation>扭转时段的起点，即自录制开始起的秒数（0：从头开始）</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>end</source>
        <translation>结尾</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>End of the twists, in seconds since the recording began (end: to the end of the session)</source>
        <translation>扭转时段的终点，即自录制开始起的秒数（结尾：直到会话结束）</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Device</source>
        <translation>设备</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Offset (ms)</source>
        <translation>偏移（ms）</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>± (ms)</source>
        <translation>±（ms）</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Correlation</source>
        <translation>相关系数</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Twists</source>
        <translation>扭转次数</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Status</source>
        <translation>状态</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Added to the device&apos;s times to put them on the reference&apos;s, in milliseconds</source>
        <translation>加到该设备的时间上，使其与参考设备的时间一致，单位为毫秒</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>One standard deviation of the offset, in milliseconds</source>
        <translation>偏移的一倍标准差，单位为毫秒</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Normalised correlation at the offset (-1 to 1); a good match is close to 1</source>
        <translation>该偏移处的归一化相关系数（-1 到 1）；匹配良好时接近 1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Sharp turns found in the device&apos;s gyro magnitude</source>
        <translation>在该设备陀螺仪角速度模值中找到的急速转动次数</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>Find offsets</source>
        <translation>计算偏移</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Read the captures and cross-correlate each device&apos;s gyro magnitude with the reference&apos;s</source>
        <translation>读取采集文件，将各设备的陀螺仪角速度模值与参考设备的做互相关</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Store offsets</source>
        <translation>保存偏移</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Write the offsets found into the session&apos;s session.json; export and replay use them</source>
        <translation>将求得的偏移写入该会话的 session.json；导出和回放时会使用这些偏移</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>to</source>
        <translation>至</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Session:</source>
        <translation>会话：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Reference device:</source>
        <translation>参考设备：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Twists from:</source>
        <translation>扭转时段：</translation>
    </message>
    <message>
        <location line="+47"/>
        <location line="+167"/>
        <source>The session in %1 has one device only: twist to align needs two or more devices recorded together. Choose another session.</source>
        <translation>%1 中的会话只有一台设备：扭转对齐需要两台或以上一起录制的设备。请选择其他会话。</translation>
    </message>
    <message>
        <location line="-164"/>
        <source>Press Find offsets to search the session&apos;s %1 devices for the twists.</source>
        <translation>请按“计算偏移”，在该会话的 %1 台设备中查找扭转动作。</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>First device with gyroscope data</source>
        <translation>第一台有陀螺仪数据的设备</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Choose the folder of a recorded session (the folder with session.json).</source>
        <translation>请选择已录制会话的文件夹（包含 session.json 的文件夹）。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 is not a folder. Choose the folder of a recorded session.</source>
        <translation>%1 不是文件夹。请选择已录制会话的文件夹。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 is not a recorded session: it has no session.json. Choose the folder a recording of several devices wrote.</source>
        <translation>%1 不是已录制的会话：其中没有 session.json。请选择多设备录制所生成的文件夹。</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>The session in %1 cannot be read (%2). Choose another session folder.</source>
        <translation>无法读取 %1 中的会话（%2）。请选择其他会话文件夹。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The session in %1 lists no device. Choose another session folder.</source>
        <translation>%1 中的会话未列出任何设备。请选择其他会话文件夹。</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>Open a recorded session</source>
        <translation>打开已录制的会话</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Close</source>
        <translation>关闭</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stop the search; nothing is changed</source>
        <translation>停止搜索；不做任何更改</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Close this window</source>
        <translation>关闭此窗口</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>stored earlier (%1)</source>
        <translation>此前已保存（%1）</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>not searched yet</source>
        <translation>尚未搜索</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>The end of the twists (%1 s) must be later than their start (%2 s); set To to end for the whole rest of the session.</source>
        <translation>扭转时段的终点（%1 s）必须晚于起点（%2 s）；如需覆盖会话的其余全部，请将终点设为“结尾”。</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Reading the captures of %1 devices…</source>
        <translation>正在读取 %1 台设备的采集文件…</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Widen From and To, or set them to 0 and end for the whole session.</source>
        <translation>请放宽扭转时段的起点和终点，或将其设为 0 和“结尾”以覆盖整个会话。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Search cancelled; nothing was changed.</source>
        <translation>搜索已取消；未做任何更改。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>No device of the session has gyroscope data with a common time in the searched part. %1 Devices need gyroscope output (HI91) while recording.</source>
        <translation>该会话中没有任何设备在搜索范围内有带公共时间的陀螺仪数据。%1 录制时设备需要输出陀螺仪数据（HI91）。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The reference %1 has no gyroscope data with a common time in the searched part. Choose another reference device. %2</source>
        <translation>参考设备 %1 在搜索范围内没有带公共时间的陀螺仪数据。请选择其他参考设备。%2</translation>
    </message>
    <message>
        <location line="+57"/>
        <source>Aligned to %1: devices aligned %2 of %3. Check that the correlation is close to 1 and the ± column small, then press Store offsets.</source>
        <translation>已对齐到 %1：%3 台设备中已对齐 %2 台。请检查相关系数是否接近 1、± 列是否足够小，然后按“保存偏移”。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>No device could be aligned to %1: see the Status column. Record the twists again (turn the fixture sharply at least 3 times at irregular intervals while every device records), or set From and To around the twists.</source>
        <translation>没有设备能对齐到 %1：请查看“状态”列。请重新录制扭转动作（在所有设备录制期间，以不规则的间隔急速转动工装至少 3 次），或将起点和终点设在扭转动作的前后。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The captures of %1 could not be read: check that the session folder holds every file session.json names.</source>
        <translation>无法读取 %1 的采集文件：请检查会话文件夹中是否有 session.json 列出的所有文件。</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Capture unreadable: %1</source>
        <translation>采集文件无法读取：%1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>reference</source>
        <translation>参考设备</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>No gyroscope data with a common time in the searched part; left as it was.</source>
        <translation>搜索范围内没有带公共时间的陀螺仪数据；保持原样。</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>aligned</source>
        <translation>已对齐</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Not aligned: %1</source>
        <translation>未对齐：%1</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>The search is still running: wait for it to end, then store the offsets.</source>
        <translation>搜索仍在进行：请等待其结束后再保存偏移。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Nothing to store: no device is aligned. Press Find offsets first.</source>
        <translation>没有可保存的内容：没有任何设备已对齐。请先按“计算偏移”。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The session in %1 cannot be read any more (%2): nothing was stored. Check the folder, then find the offsets again.</source>
        <translation>已无法读取 %1 中的会话（%2）：未保存任何内容。请检查该文件夹，然后重新计算偏移。</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The devices in %1 changed since the search: nothing was stored. Find the offsets again.</source>
        <translation>搜索之后 %1 中的设备已发生变化：未保存任何内容。请重新计算偏移。</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>The offsets could not be stored (%1). Check that the session folder is writable, then press Store offsets again.</source>
        <translation>无法保存偏移（%1）。请检查会话文件夹是否可写，然后再次按“保存偏移”。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Offsets stored in %2 (devices aligned: %1); export and replay of the session use them.</source>
        <translation>偏移已保存到 %2（已对齐设备：%1 台）；导出和回放该会话时会使用这些偏移。</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::UserGuideDialog</name>
    <message>
        <location filename="../ui/workspace/help_dialogs.cpp" line="-195"/>
        <source>The user guide is written in English; it is not available in your language yet. The menus and dialogs it describes are shown in your language.</source>
        <translation>用户指南以英文编写，暂无您所用语言的版本。指南中描述的菜单和对话框以您的语言显示。</translation>
    </message>
    <message>
        <location line="+69"/>
        <source>ImuDesk user guide</source>
        <translation>ImuDesk 用户指南</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Contents</source>
        <translation>目录</translation>
    </message>
    <message>
        <location line="-37"/>
        <source>The user guide is not part of this build. It is docs/USER_GUIDE.md in ImuDesk&apos;s source.</source>
        <translation>此版本未包含用户指南。它位于 ImuDesk 源代码中的 docs/USER_GUIDE.md。</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::VerifyModuleWizard</name>
    <message>
        <location filename="../ui/calibration/verify_module_wizard.cpp" line="+47"/>
        <source>Verify module</source>
        <translation>验证模块</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Turn the module through still poses</source>
        <translation>将模块依次转到各个静止姿态</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Press Start, then hold the module still for 3 s in each orientation below (every face up and down, then between them) and turn it to the next; the order does not matter. 9 poses are needed, 12 give the best figures. Keep it away from steel and magnets.</source>
        <translation>按“开始”，然后让模块在下面每个朝向（每个面朝上和朝下，再加上它们之间的朝向）各保持静止 3 s，再转到下一个；顺序不限。至少需要 9 个姿态，12 个可得到最好的结果。请远离钢铁和磁铁。</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>The bench&apos;s latitude (degrees, north positive): its normal gravity, WGS 84</source>
        <translation>测试台所在纬度（度，北纬为正）：用于计算 WGS 84 正常重力</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The bench&apos;s height above the ellipsoid (metres)</source>
        <translation>测试台的椭球高（米）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Measured gravity:</source>
        <translation>实测重力：</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The bench&apos;s gravity from a survey (m/s²), instead of latitude and height</source>
        <translation>测量得到的测试台重力值（m/s²），代替纬度和高度</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>height</source>
        <translation>高度</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Bench latitude:</source>
        <translation>测试台纬度：</translation>
    </message>
    <message>
        <location line="+13"/>
        <location line="+182"/>
        <source>Press Start.</source>
        <translation>请按“开始”。</translation>
    </message>
    <message>
        <location line="-172"/>
        <source>%v of 12 poses</source>
        <translation>%v / 12 个姿态</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Start</source>
        <translation>开始</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Start recording the poses (Ctrl+R)</source>
        <translation>开始记录姿态（Ctrl+R）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stop</source>
        <translation>停止</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Result</source>
        <translation>结果</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Figure</source>
        <translation>项目</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Value</source>
        <translation>数值</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>95 % bound</source>
        <translation>95 % 界限</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Limits (pass / fail)</source>
        <translation>限值（通过 / 不合格）</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Verdict</source>
        <translation>判定</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Export report (PDF)…</source>
        <translation>导出报告（PDF）…</translation>
    </message>
    <message>
        <location line="+86"/>
        <source>The recording is full (%1 samples): press Next.</source>
        <translation>记录已满（%1 个样本）：请按“下一步”。</translation>
    </message>
    <message>
        <location line="+47"/>
        <source>Recorded: press Next for the result.</source>
        <translation>已记录：按“下一步”查看结果。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stopped: press Start to record again, or Next to judge what was recorded.</source>
        <translation>已停止：按“开始”重新记录，或按“下一步”判定已记录的数据。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Turn the module to the next pose.</source>
        <translation>将模块转到下一个姿态。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Hold still: %1 s</source>
        <translation>保持静止：%1 s</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Pose recorded: turn to the next.</source>
        <translation>姿态已记录：转到下一个。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 distinct poses held (9 needed, 12 suggested); %2 s recorded, %3 samples.</source>
        <translation>已保持 %1 个不同姿态（至少 9 个，建议 12 个）；已记录 %2 s，%3 个样本。</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Nothing recorded yet: press Start and turn the module through the poses.</source>
        <translation>尚未记录：请按“开始”并将模块依次转到各个姿态。</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>Verdict: %1</source>
        <translation>判定：%1</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Accelerometer bias (mg; X, Y, Z)</source>
        <translation>加速度计零偏（mg；X、Y、Z）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Accelerometer scale error (%; X, Y, Z)</source>
        <translation>加速度计标度因数误差（%；X、Y、Z）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Accelerometer misalignment, largest (°)</source>
        <translation>加速度计轴间失准，最大值（°）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Gyro bias (°/s; X, Y, Z)</source>
        <translation>陀螺仪零偏（°/s；X、Y、Z）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Gyro scale error (%; X, Y, Z)</source>
        <translation>陀螺仪标度因数误差（%；X、Y、Z）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Gyro misalignment, largest (°)</source>
        <translation>陀螺仪轴间失准，最大值（°）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Roll error (°)</source>
        <translation>横滚误差（°）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Pitch error (°)</source>
        <translation>俯仰误差（°）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Heading error (°)</source>
        <translation>航向误差（°）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Attitude error while moving, RMS (°)</source>
        <translation>运动中的姿态误差，RMS（°）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Attitude lag (ms)</source>
        <translation>姿态滞后（ms）</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>%1 still intervals, %2 distinct poses, gravity %3 m/s²</source>
        <translation>%1 个静止区间，%2 个不同姿态，重力 %3 m/s²</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Verify module wizard</source>
        <translation>验证模块向导</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>Export report</source>
        <translation>导出报告</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PDF (*.pdf)</source>
        <translation>PDF (*.pdf)</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Report written to %1</source>
        <translation>报告已写入 %1</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::WindowHelpers</name>
    <message>
        <location filename="../ui/common/window_helpers.cpp" line="+31"/>
        <source>Could not save the screenshot to %1: %2</source>
        <translation>无法将截图保存到 %1：%2</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::YieldView</name>
    <message>
        <location filename="../ui/results/yield_view.cpp" line="+54"/>
        <source>Modules</source>
        <translation>模块</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Pass</source>
        <translation>通过</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Fail</source>
        <translation>失败</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Marginal</source>
        <translation>临界</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Error</source>
        <translation>错误</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Aborted</source>
        <translation>中止</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Yield</source>
        <translation>良率</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Passed, with a value beyond its marginal band (counted among the passes too)</source>
        <translation>通过，但有数值超出临界带（同时计入通过数）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Pass / (pass + fail)</source>
        <translation>通过 / (通过 + 失败)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>ERROR (the equipment failed: a port went away, a module did not answer) and ABORTED (the operator cancelled) are not counted in the yield: yield = pass / (pass + fail).</source>
        <translation>错误（设备故障：串口断开、模块无应答）和中止（操作员取消）不计入良率：良率 = 通过 / (通过 + 失败)。</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>Plan %1, since %2</source>
        <translation>测试计划 %1，自 %2 起</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Plan %1, every module</source>
        <translation>测试计划 %1，全部模块</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>All modules</source>
        <translation>全部模块</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Firmware %1</source>
        <translation>固件 %1</translation>
    </message>
    <message>
        <location line="+0"/>
        <location line="+2"/>
        <source>(unknown)</source>
        <translation>（未知）</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Slot %1</source>
        <translation>工位 %1</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <location filename="../app/gui/main.cpp" line="+95"/>
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
        <source>Start connected to a simulated HI14 (firmware 1.7.1) that tumbles slowly through every orientation.</source>
        <translation>启动后连接到一个模拟 HI14（固件 1.7.1），它会缓慢翻滚，经历所有姿态。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Save the main window to this PNG file and quit (see --after).</source>
        <translation>将主窗口保存为此 PNG 文件后退出（参见 --after）。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Seconds to wait before --screenshot (default 3).</source>
        <translation>执行 --screenshot 前等待的秒数（默认 3）。</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Bring this panel to the front: configuration, recording, console, raw, commands, can (the CAN configuration) or sync (the clocks).</source>
        <translation>将此面板置于最前：configuration（配置）、recording（记录）、console（控制台）、raw（原始字节）、commands（指令日志）、can（CAN 配置）或 sync（时钟）。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Open Twist to align on a recorded session&apos;s FOLDER and find the devices&apos; offsets. With --screenshot the dialog is saved.</source>
        <translation>在已录制会话的文件夹 FOLDER 上打开“扭转对齐”，并计算各设备的偏移。与 --screenshot 同用时保存该对话框。</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Start the live bridge (Tools &gt; Live bridge) on ADDR:PORT, e.g. 127.0.0.1:8765: the connected devices to Foxglove, Lichtblick and PlotJuggler.</source>
        <translation>在 ADDR:PORT（例如 127.0.0.1:8765）上启动实时桥接（工具 &gt; 实时桥接）：将已连接的设备发送到 Foxglove、Lichtblick 和 PlotJuggler。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Open Device &gt; Find devices… at start (a first start without a device to open does so anyway).</source>
        <translation>启动时打开“设备 &gt; 查找设备…”（首次启动且没有要打开的设备时也会自动打开）。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Open Device &gt; Find devices… on a simulated bench (six devices on four ports and a virtualcan bus, two of them sharing a node ID) and sweep it.</source>
        <translation>在模拟测试台（四个端口和一条 virtualcan 总线上的六台设备，其中两台共用一个节点 ID）上打开“设备 &gt; 查找设备…”并进行扫描。</translation>
    </message>
    <message>
        <location line="+136"/>
        <source>Unknown panel &quot;%1&quot;; use configuration, recording, console, raw, commands, can or sync.</source>
        <translation>未知的面板“%1”；请使用 configuration、recording、console、raw、commands、can 或 sync。</translation>
    </message>
    <message>
        <location line="-156"/>
        <source>Open the production station window; with PLAN (a test plan file), load that plan. With --screenshot the station window is saved.</source>
        <translation>打开生产测试台窗口；指定 PLAN（测试计划文件）时加载该计划。使用 --screenshot 时保存的是生产测试台窗口。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Open the production station with a simulated tray of 8 HI14 modules (one with a noisy gyro, one mounted wrongly, one with firmware 1.6.6) and run PLAN on it; without PLAN the built-in example plan, its firmware step without an image (the old module fails it) and its profile step off.</source>
        <translation>打开生产测试台，使用装有 8 个 HI14 模块的模拟托盘（一个陀螺仪噪声过大，一个安装方向错误，一个固件为 1.6.6），并在其上运行 PLAN；未指定 PLAN 时运行内置示例计划，其固件步骤不含镜像（旧固件模块在此步骤失败），配置方案步骤禁用。</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>Test plan for --station or --station-demo.</source>
        <translation>--station 或 --station-demo 使用的测试计划。</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Give either a model (--simulate) or a plan (--station), not both.</source>
        <translation>请指定型号（--simulate）或测试计划（--station），二者不能同时指定。</translation>
    </message>
    <message>
        <location line="-13"/>
        <source>Model to simulate with --simulate (default HI14).</source>
        <translation>--simulate 模拟的型号（默认 HI14）。</translation>
    </message>
    <message>
        <location line="-42"/>
        <source>Start connected to another simulated device: hec495 (compass on serial), modbus (HI14 over Modbus RTU), can (HI14 J1939 on virtualcan) or canopen (HI14 CANopen on virtualcan); or replay a capture file, or a recorded session (its session.json or folder).</source>
        <translation>启动时连接另一种模拟设备：hec495（串口电子罗盘）、modbus（Modbus RTU 上的 HI14）、can（virtualcan 上的 HI14 J1939）或 canopen（virtualcan 上的 HI14 CANopen）；或回放一个记录文件，或一个已录制的会话（其 session.json 或文件夹）。</translation>
    </message>
    <message>
        <location line="+58"/>
        <source>A model name is only accepted after --simulate.</source>
        <translation>型号名称只能跟在 --simulate 之后。</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>--after needs a number of seconds from 0 to 3600.</source>
        <translation>--after 需要 0 到 3600 之间的秒数。</translation>
    </message>
    <message>
        <location line="+3"/>
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
        <location line="+5"/>
        <source>Unknown motion &quot;%1&quot;; use static, spin or tumble.</source>
        <translation>未知的运动方式“%1”；请使用 static、spin 或 tumble。</translation>
    </message>
    <message>
        <location line="+23"/>
        <location line="+26"/>
        <location line="+60"/>
        <source>ImuDesk</source>
        <translation>ImuDesk</translation>
    </message>
</context>
</TS>
