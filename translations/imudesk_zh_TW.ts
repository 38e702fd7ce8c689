<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="zh_TW">
<context>
    <name>BandwidthCalculator</name>
    <message>
        <location filename="../core/settings/bandwidth_calculator.cpp" line="+70"/>
        <source>The output needs %1 bytes/s but %2 baud carries only %3 bytes/s (%4 %): frames will be lost. %5</source>
        <translation>輸出需要 %1 位元組/s，但 %2 波特率只能傳送 %3 位元組/s（%4 %）：將會遺失資料幀。%5</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Raise the baud rate to %1 or lower the rates.</source>
        <translation>請將波特率提高到 %1，或降低輸出頻率。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Lower the rates or turn some messages off.</source>
        <translation>請降低輸出頻率，或關閉部分訊息。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The output uses %1 % of the link at %2 baud: little margin left, a higher baud rate is safer.</source>
        <translation>輸出佔用 %2 波特率鏈路的 %1 %：餘量很小，使用較高的波特率較安全。</translation>
    </message>
</context>
<context>
    <name>CalibrationHistory</name>
    <message>
        <location filename="../core/calib/calibration_history.cpp" line="+82"/>
        <source>A calibration record needs a kind.</source>
        <translation>校準記錄必須指定類型。</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Cannot create the folder %1: check that the disk is writable.</source>
        <translation>無法建立資料夾 %1：請確認磁碟可寫入。</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+3"/>
        <location line="+3"/>
        <location line="+3"/>
        <source>Cannot write %1: %2</source>
        <translation>無法寫入 %1：%2</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>%1 is too large to load.</source>
        <translation>%1 過大，無法載入。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Cannot read %1: %2</source>
        <translation>無法讀取 %1：%2</translation>
    </message>
</context>
<context>
    <name>CalibrationReport</name>
    <message>
        <location filename="../ui/calibration/calibration_report.cpp" line="+36"/>
        <source>Fit</source>
        <translation>擬合方式</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Soft-iron matrix (rows, unitless)</source>
        <translation>軟鐵矩陣（按列，無單位）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Fit error (%)</source>
        <translation>擬合誤差（%）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Sphere coverage (%)</source>
        <translation>球面覆蓋率（%）</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Soft-iron uncertainty, RMS (%)</source>
        <translation>軟磁不確定度，RMS (%)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Eigenvalue ratio (max/min)</source>
        <translation>特徵值比（最大/最小）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Samples fitted</source>
        <translation>參與擬合的樣本數</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Samples set aside as outliers</source>
        <translation>剔除為離群值的樣本數</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Hard-iron-only fit offered</source>
        <translation>提供僅硬鐵擬合</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Planar (2-D) fit offered</source>
        <translation>提供平面（二維）擬合</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Vertical offset known</source>
        <translation>垂直方向偏移已知</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Target angle (deg)</source>
        <translation>目標角度（deg）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Device accepted</source>
        <translation>裝置已接受</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Device reply</source>
        <translation>裝置回應</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>ImuDesk estimate available</source>
        <translation>已有 ImuDesk 估計值</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Scale error, ImuDesk estimate (%)</source>
        <translation>標度誤差，ImuDesk 估計值（%）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Angle turned (deg)</source>
        <translation>轉動角度（deg）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Duration (s)</source>
        <translation>持續時間（s）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Mean rate (deg/s)</source>
        <translation>平均轉速（deg/s）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Time in the 20-100 deg/s band (%)</source>
        <translation>處於 20-100 deg/s 範圍內的時間比例（%）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Rate unevenness, std/mean (%)</source>
        <translation>轉速不均勻度，標準差/平均值（%）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stopped within +-5 deg of the target</source>
        <translation>停在目標 +-5 deg 以內</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Run met the manual&apos;s conditions</source>
        <translation>本輪操作符合手冊條件</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Gyro bias along the axis (deg/s)</source>
        <translation>沿轉軸的陀螺儀零偏（deg/s）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Axis tilt from sensor z (deg)</source>
        <translation>轉軸相對感測器 z 軸的傾角（deg）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Output rate (Hz)</source>
        <translation>輸出速率（Hz）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Variant (ATT RST)</source>
        <translation>選項（ATT RST）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Command sent</source>
        <translation>已傳送指令</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Still for, when sent (s)</source>
        <translation>傳送時已靜止時間（s）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Gyro spread, when sent (deg/s)</source>
        <translation>傳送時陀螺儀波動（deg/s）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Accelerometer spread, when sent (G)</source>
        <translation>傳送時加速度計波動（G）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Roll before (deg)</source>
        <translation>重設前橫滾角（deg）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Pitch before (deg)</source>
        <translation>重設前俯仰角（deg）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Roll after (deg)</source>
        <translation>重設後橫滾角（deg）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Pitch after (deg)</source>
        <translation>重設後俯仰角（deg）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Yaw after (deg)</source>
        <translation>重設後航向角（deg）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Method</source>
        <translation>方法</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Start command byte</source>
        <translation>啟動指令位元組</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>FitErr (module&apos;s fit error)</source>
        <translation>FitErr（模組的擬合誤差）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>FitErr limit (manual)</source>
        <translation>FitErr 上限（手冊）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Points used</source>
        <translation>使用點數</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Valid points collected</source>
        <translation>已採集有效點數</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>unbounded</source>
        <translation>無界</translation>
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
        <translation>ImuDesk 校準報告：%1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Device</source>
        <translation>裝置</translation>
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
        <translation>磁場強度 |B| (µT)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Hard iron x, y, z (µT)</source>
        <translation>硬鐵 x, y, z (µT)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Residual RMS (µT)</source>
        <translation>殘差 RMS (µT)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Predicted heading error, level module, 68 % bound (deg)</source>
        <translation>預測航向誤差，水平模組，68 % 界限（deg）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Predicted heading error, level module, 95 % bound (deg)</source>
        <translation>預測航向誤差，水平模組，95 % 界限（deg）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Hard-iron uncertainty, RMS (µT)</source>
        <translation>硬鐵不確定度，RMS (µT)</translation>
    </message>
    <message>
        <location line="+176"/>
        <source>Serial number</source>
        <translation>序號</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Firmware</source>
        <translation>韌體</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Time (UTC)</source>
        <translation>時間（UTC）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Calibration</source>
        <translation>校準</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Samples recorded</source>
        <translation>記錄的樣本數</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Verdict:</source>
        <translation>判定：</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Metrics</source>
        <translation>指標</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Metric</source>
        <translation>指標</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Value</source>
        <translation>數值</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Magnetometer samples</source>
        <translation>磁力計樣本</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Troubleshooting (HiPNUC manual v1.7.1, 9.31 and 9.32)</source>
        <translation>故障排除（HiPNUC 手冊 v1.7.1，9.31 與 9.32）</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Cause</source>
        <translation>失敗原因</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Typical sign</source>
        <translation>典型現象</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>What to do</source>
        <translation>解決方案</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Strong magnetic interference around</source>
        <translation>環境磁場干擾過大</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>STAT=4 or a jumping heading</source>
        <translation>STAT=4 或航向角跳變</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Calibrate outdoors in an open space</source>
        <translation>更換校準環境至戶外空曠處</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Rotation not done as described</source>
        <translation>旋轉動作不規範</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>PROGRESS grows slowly or stops</source>
        <translation>PROGRESS 增長緩慢或停滯</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Turn fully and evenly about every axis</source>
        <translation>確保每個軸充分旋轉，速度均勻</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The module moved while turning</source>
        <translation>旋轉時位置移動</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Calibration finishes but the heading is poor</source>
        <translation>校準完成但精度差</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Keep it in place, only turn it</source>
        <translation>校準時保持位置固定，僅旋轉姿態</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Module and carrier moved relative to each other</source>
        <translation>模組與載體位置變化</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Larger heading error after remounting</source>
        <translation>重新安裝後航向角誤差增大</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Calibrate the module and the carrier again, as one</source>
        <translation>將模組與載體作為整體重新校準</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Indoors the field is often distorted in ways no calibration removes: if the heading stays poor after a good calibration, prefer the 6-axis mode there.</source>
        <translation>室內磁場畸變往往無法透過校準消除：若校準良好後航向角精度仍然不佳，在室內請優先使用 6 軸模式。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Written by ImuDesk from the run kept in %1</source>
        <translation>由 ImuDesk 根據 %1 中保存的校準資料產生</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Left: the %1 samples of the run as measured (raw). Right: the same samples corrected by the run&apos;s hard and soft iron; the green cells are the directions they cover, %2 % of the sphere.</source>
        <translation>左：本次校準測得的 %1 個樣本（原始資料）。右：以本次的硬鐵和軟鐵校正後的同一批樣本；綠色單元為它們覆蓋的方向，佔球面的 %2 %。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The %1 samples of the run as measured (raw), around their mean; the green cells are the directions they point to. The run has no usable correction to show them corrected.</source>
        <translation>本次校準測得的 %1 個樣本（原始資料），以其平均值為中心；綠色單元為它們指向的方向。本次沒有可用的校正，無法顯示校正後的樣本。</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>still running</source>
        <translation>仍在執行</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Last reply: STAT=%1, PROGRESS=%2.</source>
        <translation>最後一次回應：STAT=%1，PROGRESS=%2。</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>The device&apos;s own calibration</source>
        <translation>裝置自身的校準</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The module&apos;s calibration (MCAL) is a separate run with its own verdict; the verdict and the metrics above are ImuDesk&apos;s fit of the raw samples.</source>
        <translation>模組自身的校準（MCAL）是另一次獨立的執行，有自己的結論；上面的結論和指標是 ImuDesk 對原始樣本的擬合。</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>ImuDesk calibration report</source>
        <translation>ImuDesk 校準報告</translation>
    </message>
    <message>
        <location filename="../ui/calibration/calibration_history_dialog.cpp" line="+236"/>
        <location filename="../ui/calibration/calibration_report.cpp" line="-11"/>
        <source>Device&apos;s verdict:</source>
        <translation>裝置的結論：</translation>
    </message>
</context>
<context>
    <name>CalibrationRunSaver</name>
    <message>
        <location filename="../ui/calibration/calibration_run_saver.cpp" line="+48"/>
        <source>Saved in the calibration history (Calibrate &gt; Calibration history): %1</source>
        <translation>已儲存到校準歷史（校準 &gt; 校準歷史）：%1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>This run could not be saved in the calibration history: %1 The result is still shown here; free some disk space or check the folder&apos;s permissions to keep the next run.</source>
        <translation>本輪校準無法儲存到校準歷史：%1 結果仍顯示於此；請釋放磁碟空間或檢查資料夾權限，以便保存下一輪校準。</translation>
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
        <translation>HEC495 %1 軸：%2</translation>
    </message>
    <message>
        <location line="+8"/>
        <location line="+92"/>
        <source>HEC495 write 0x%1 confirmed</source>
        <translation>HEC495 寫入 0x%1 已確認</translation>
    </message>
    <message>
        <location line="-91"/>
        <location line="+92"/>
        <source>HEC495 write %1</source>
        <translation>HEC495 寫入 %1</translation>
    </message>
    <message>
        <location line="-78"/>
        <source>PGN %1 %2: date unknown, not UTC (module clock %3:%4:%5.%6)</source>
        <translation>PGN %1 %2：日期未知，不是 UTC（模組時鐘 %3:%4:%5.%6）</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>PGN %1 %2: %3-%4-%5 %6:%7:%8.%9</source>
        <translation>PGN %1 %2：%3-%4-%5 %6:%7:%8.%9</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>heading %1 deg (CW); %2</source>
        <translation>航向角 %1 deg（順時針）；%2</translation>
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
        <translation>NMT 指令 0x%1 發往節點 %2</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>SYNC</source>
        <translation>SYNC</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>heartbeat node %1: %2</source>
        <translation>節點 %1 心跳：%2</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>node %1: </source>
        <translation>節點 %1：</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>to node %1: </source>
        <translation>發往節點 %1：</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>HEC495 PDO %1 (%2): %3</source>
        <translation>HEC495 PDO %1（%2）：%3</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>fixed</source>
        <translation>定點數</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>float</source>
        <translation>浮點數</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>TPDO%1 %2: %3</source>
        <translation>TPDO%1 %2：%3</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>TPDO with a wrong length (%1 bytes)</source>
        <translation>TPDO 長度錯誤（%1 位元組）</translation>
    </message>
</context>
<context>
    <name>CanSettingCatalog</name>
    <message>
        <location filename="../core/protocol/can/can_setting_catalog.cpp" line="+79"/>
        <source>default</source>
        <translation>預設</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>reversed</source>
        <translation>反向</translation>
    </message>
    <message>
        <location line="+79"/>
        <source>UTC time (FF2F) interval</source>
        <translation>UTC 時間 (FF2F) 傳送間隔</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Acceleration (FF34) interval</source>
        <translation>加速度 (FF34) 傳送間隔</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Angular rate (FF37) interval</source>
        <translation>角速度 (FF37) 傳送間隔</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Magnetic field (FF3A) interval</source>
        <translation>磁場 (FF3A) 傳送間隔</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Pitch and roll (FF3D) interval</source>
        <translation>俯仰橫滾 (FF3D) 傳送間隔</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Heading (FF41) interval</source>
        <translation>航向角 (FF41) 傳送間隔</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Quaternion (FF46) interval</source>
        <translation>四元數 (FF46) 傳送間隔</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Inclinometer (FF4A) interval</source>
        <translation>傾角儀 (FF4A) 傳送間隔</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CAN FD frame 0 (FF5A) interval</source>
        <translation>CAN FD 資料幀 0 (FF5A) 傳送間隔</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>only on a module with CAN FD output enabled; the manual gives no command to enable it</source>
        <translation>僅在啟用 CAN FD 輸出的模組上有效；手冊未給出啟用它的命令</translation>
    </message>
    <message>
        <location line="-123"/>
        <source>CAN bit rate</source>
        <translation>CAN 鮑率</translation>
    </message>
    <message>
        <location line="+77"/>
        <source>the serial port&apos;s baud rate; takes effect after save and reset</source>
        <translation>串列埠鮑率；儲存並復位後生效</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the Modbus address of the serial port</source>
        <translation>串列埠的 Modbus 位址</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>6-axis (relative heading)</source>
        <translation>6 軸（相對航向）</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>9-axis (absolute heading)</source>
        <translation>9 軸（絕對航向）</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>v1.6.6: 0-4; v1.7.1: the URFR code (0x18 = 024 ...); the manual gives no read</source>
        <translation>v1.6.6：0-4；v1.7.1：URFR 代碼（0x18 = 024 ...）；手冊未提供讀取方式</translation>
    </message>
    <message>
        <location line="+5"/>
        <location line="+233"/>
        <source>read only</source>
        <translation>唯讀</translation>
    </message>
    <message>
        <location line="-204"/>
        <location line="+47"/>
        <location line="+3"/>
        <source>takes effect after save and reset</source>
        <translation>儲存並重設後生效</translation>
    </message>
    <message>
        <location line="-49"/>
        <source>Source address (node ID)</source>
        <translation>來源位址（節點 ID）</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+81"/>
        <source>Data output</source>
        <translation>資料輸出</translation>
    </message>
    <message>
        <location line="-79"/>
        <location line="+67"/>
        <location line="+14"/>
        <source>off</source>
        <translation>關</translation>
    </message>
    <message>
        <location line="-81"/>
        <location line="+81"/>
        <source>on</source>
        <translation>開</translation>
    </message>
    <message>
        <location line="-79"/>
        <location line="+45"/>
        <source>Inclinometer X direction</source>
        <translation>傾角儀 X 軸方向</translation>
    </message>
    <message>
        <location line="-43"/>
        <location line="+45"/>
        <source>Inclinometer Y direction</source>
        <translation>傾角儀 Y 軸方向</translation>
    </message>
    <message>
        <location line="-43"/>
        <source>Firmware version</source>
        <translation>韌體版本</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>TPDO%1 (%2) period</source>
        <translation>TPDO%1（%2）週期</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+14"/>
        <source>0 = off</source>
        <translation>0 = 關閉</translation>
    </message>
    <message>
        <location line="-12"/>
        <source>TPDO%1 transmission</source>
        <translation>TPDO%1 傳輸方式</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>on each SYNC</source>
        <translation>每個 SYNC 傳送</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>timed (0xFE)</source>
        <translation>定時 (0xFE)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>timed (0xFF)</source>
        <translation>定時 (0xFF)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Heartbeat period</source>
        <translation>心跳週期</translation>
    </message>
    <message>
        <location line="+7"/>
        <location line="+45"/>
        <source>Node ID</source>
        <translation>節點 ID</translation>
    </message>
    <message>
        <location line="-31"/>
        <source>written only: the manual documents no way to read it back</source>
        <translation>只能寫入：手冊未說明如何讀回</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Output rate</source>
        <translation>輸出速率</translation>
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
        <translation>浮點</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>fixed point</source>
        <translation>定點</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>float, 0x180/0x280 only</source>
        <translation>浮點，僅 0x180/0x280</translation>
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
        <translation>重新上電後生效</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>code %1 (not in the manual)</source>
        <translation>代碼 %1（手冊中沒有）</translation>
    </message>
    <message>
        <location line="+39"/>
        <source>%1 is read only</source>
        <translation>%1 為唯讀</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>%1: &quot;%2&quot; is not a number (%3)</source>
        <translation>%1：“%2”不是數字（%3）</translation>
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
        <translation>僅監聽匯流排期間，節點 %1 送出了兩次開機訊息：有兩台裝置以該節點 ID 啟動</translation>
    </message>
    <message>
        <location line="+84"/>
        <source>SDO read of %1:%2</source>
        <translation>對 %1:%2 的 SDO 讀取</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>J1939 read of register %1</source>
        <translation>對暫存器 %1 的 J1939 讀取</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>refused</source>
        <translation>被拒絕</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 answers from node %2 to one %3, with different contents (%4)</source>
        <translation>節點 %2 對同一次%3給出 %1 個回應，內容不同（%4）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 answers from node %2 to one %3 (%4)</source>
        <translation>節點 %2 對同一次%3給出 %1 個回應（%4）</translation>
    </message>
    <message>
        <location line="+51"/>
        <source>HiPNUC module (J1939)</source>
        <translation>HiPNUC 模組（J1939）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>HiPNUC module (CANopen)</source>
        <translation>HiPNUC 模組（CANopen）</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>vendor %1, product code %2</source>
        <translation>廠商 %1，產品代碼 %2</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>the module&apos;s own bit-rate setting (the interface cannot measure one)</source>
        <translation>模組本身的鮑率設定（該介面無法量得鮑率）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>sends no data; answered when asked</source>
        <translation>不主動傳送資料；詢問時有回應</translation>
    </message>
    <message numerus="yes">
        <location line="+8"/>
        <source>%1 (and %n more time(s) like it)</source>
        <translation>
            <numerusform>%1（另有 %n 次同類情況）</numerusform>
        </translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Power the devices one at a time and give each its own node ID (its CAN tab, Settings, node ID; save and reset), then sweep again.</source>
        <translation>逐台為裝置上電，並為每台設定各自的節點 ID（在其 CAN 分頁的「設定」中修改節點 ID，儲存並重設），然後重新掃描。</translation>
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
        <translation>CAN 幀</translation>
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
        <translation>閒置</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>checking the image</source>
        <translation>正在檢查映像</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>identifying the module</source>
        <translation>正在識別模組</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>entering the bootloader</source>
        <translation>正在進入開機載入程式</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>confirming the bootloader</source>
        <translation>正在確認開機載入程式</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>downloading</source>
        <translation>正在下載</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>verifying</source>
        <translation>正在驗證</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>starting the application</source>
        <translation>正在啟動應用程式</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>confirming the new version</source>
        <translation>正在確認新版本</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>done</source>
        <translation>完成</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>failed</source>
        <translation>失敗</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cancelled</source>
        <translation>已取消</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>the image is empty</source>
        <translation>映像為空</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the image starts at %1, but the CAN bootloader writes the application at %2 (addresses are not transmitted); this is not an application image for this module</source>
        <translation>映像起始於 %1，但 CAN 開機載入程式固定將應用程式寫入 %2（位址不隨資料傳送）；這不是此模組的應用程式映像</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the image ends at %1, beyond the end of the flash at %2; it does not fit this module</source>
        <translation>映像結束於 %1，超出位於 %2 的快閃記憶體末端；無法放入此模組</translation>
    </message>
    <message>
        <location line="+92"/>
        <source>the application refused to enter its bootloader (0x1F51:05): %1</source>
        <translation>應用程式拒絕進入開機載入程式（0x1F51:05）：%1</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>the bootloader refused the confirmation (0x1F51:06): %1</source>
        <translation>開機載入程式拒絕確認請求（0x1F51:06）：%1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>no bootloader confirmation yet (attempt %1 of %2)</source>
        <translation>開機載入程式尚未確認（第 %1 次嘗試，共 %2 次）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the module did not confirm its bootloader (0x1F51:06) after %1 attempts; check the node ID and power-cycle the module</source>
        <translation>嘗試 %1 次後，模組仍未確認進入開機載入程式（0x1F51:06）；請檢查節點 ID，並將模組斷電重啟</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>cancelled after %1 of %2 bytes</source>
        <translation>在 %1 / %2 位元組後取消</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>the reply to segment %1 does not echo its data (%2); the reply is damaged</source>
        <translation>分段 %1 的回應未回傳其資料（%2）；回應已損壞</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>the bootloader did not accept the download of %1 bytes within %2 ms (it erases first)</source>
        <translation>開機載入程式未在 %2 ms 內接受 %1 位元組的下載（它會先抹除快閃記憶體）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>no reply to segment %1 (byte %2 of %3) within %4 ms</source>
        <translation>分段 %1（第 %2 / %3 位元組）在 %4 ms 內無回應</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>the bootloader refused the download of %1 bytes: %2</source>
        <translation>開機載入程式拒絕 %1 位元組的下載：%2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>segment %1 (byte %2 of %3): %4</source>
        <translation>分段 %1（第 %2 / %3 位元組）：%4</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the bootloader accepted %1 bytes (erase took %2 ms)</source>
        <translation>開機載入程式已接受 %1 位元組（抹除耗時 %2 ms）</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>the application did not answer within %1 s after the start (no boot-up, heartbeat or SDO reply); the image may not be a firmware for this module</source>
        <translation>啟動後 %1 s 內應用程式無回應（無開機訊息、心跳或 SDO 回應）；該映像可能不是此模組的韌體</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>refused before contacting the module: %1</source>
        <translation>連線模組前已拒絕：%1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>refused: node %1 is not a CANopen node ID (1..127)</source>
        <translation>已拒絕：%1 不是有效的 CANopen 節點 ID（1..127）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>image: %1 bytes at %2, CRC-32 %3</source>
        <translation>映像：%1 位元組，位於 %2，CRC-32 %3</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>node %1: application answers, firmware %2</source>
        <translation>節點 %1：應用程式已回應，韌體 %2</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>nothing answered on node %1: neither the application (SDO 0x1018:3) nor the bootloader (0x1F51:06). Check the node ID, the bit rate, the termination and the power</source>
        <translation>節點 %1 無任何回應：應用程式（SDO 0x1018:3）和開機載入程式（0x1F51:06）均未回應。請檢查節點 ID、位元速率、終端電阻和電源</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the module is already in its bootloader (an earlier update was interrupted); run the update again and allow finishing it</source>
        <translation>模組已處於開機載入程式中（先前的更新被中斷）；請重新執行更新並讓其完成</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the module is already in its bootloader: an earlier update was interrupted; finishing it</source>
        <translation>模組已處於開機載入程式中：先前的更新被中斷；正在完成更新</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>cancelled; the module was not changed</source>
        <translation>已取消；模組未變更</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>cancelled before the download; the module was not changed (if it is in its bootloader, run the update again)</source>
        <translation>下載前已取消；模組未變更（若模組處於開機載入程式中，請重新執行更新）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>bootloader confirmed on node %1</source>
        <translation>節點 %1 已確認進入開機載入程式</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>cancelled before the download; the module stays in its bootloader; run the update again to finish it</source>
        <translation>下載前已取消；模組停留在開機載入程式中；請重新執行更新以完成</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>cancelled before the download; the application was restarted unchanged</source>
        <translation>下載前已取消；應用程式已原樣重新啟動</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1. The module stays in its bootloader without a valid application; run the update again to finish it</source>
        <translation>%1。模組停留在開機載入程式中，沒有有效的應用程式；請重新執行更新以完成</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the download failed: %1. The module stays in its bootloader; run the update again</source>
        <translation>下載失敗：%1。模組停留在開機載入程式中；請重新執行更新</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 bytes sent in %2 s (%3 bytes/s)</source>
        <translation>%2 s 內傳送 %1 位元組（%3 位元組/秒）</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>verification failed: the bootloader reports CRC-32 %1 for the written application, the image has %2. The application was not started; run the update again</source>
        <translation>驗證失敗：開機載入程式回報已寫入應用程式的 CRC-32 為 %1，而映像的為 %2。應用程式未啟動；請重新執行更新</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>verified: bootloader CRC %1 equals the image&apos;s</source>
        <translation>已驗證：開機載入程式 CRC %1 與映像一致</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the bootloader offers no CRC (0x1F56:1 %1); the restart of the application is the only check</source>
        <translation>開機載入程式不提供 CRC（0x1F56:1 %1）；應用程式能否重新啟動是唯一的檢查</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not answered</source>
        <translation>未回應</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>the bootloader refused to start the application (0x1F51:09): %1. Run the update again</source>
        <translation>開機載入程式拒絕啟動應用程式（0x1F51:09）：%1。請重新執行更新</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the image was sent but %1</source>
        <translation>映像已傳送，但%1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>updated: firmware %1 → %2, %3 bytes, verified: bootloader CRC %4</source>
        <translation>已更新：韌體 %1 → %2，%3 位元組，已驗證：開機載入程式 CRC %4</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>updated: %1 bytes sent; not verified by the bootloader; application restarted with version %2</source>
        <translation>已更新：已傳送 %1 位元組；未經開機載入程式驗證；應用程式已重新啟動，版本 %2</translation>
    </message>
</context>
<context>
    <name>CaptureExporter</name>
    <message>
        <location filename="../core/record/capture_exporter.cpp" line="+116"/>
        <location line="+118"/>
        <location line="+6"/>
        <source>Cannot write %1: %2</source>
        <translation>無法寫入 %1：%2</translation>
    </message>
    <message>
        <location line="-132"/>
        <location line="+174"/>
        <location line="+28"/>
        <source>Writing %1 failed: %2. Check the free disk space.</source>
        <translation>寫入 %1 失敗：%2。請檢查可用磁碟空間。</translation>
    </message>
    <message>
        <location line="-59"/>
        <source>The capture holds %1 frame types; the vendor layout has a file for each: %2</source>
        <translation>該記錄含有 %1 種幀類型；廠商格式為每種各寫一個檔案：%2</translation>
    </message>
    <message>
        <location line="+215"/>
        <source>No output file was given.</source>
        <translation>未指定輸出檔案。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The time range is empty (from %1 s to %2 s).</source>
        <translation>時間範圍為空（從 %1 s 到 %2 s）。</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>The module reports its attitude in North-West-Up (CONFIG IMU COORD 4); the vendor CSV&apos;s layout has no column to say so: its angles and quaternion are NWU.</source>
        <translation>模組以北西天（NWU）座標系輸出姿態（CONFIG IMU COORD 4）；廠商 CSV 的格式沒有欄位可以註明：其中的角度和四元數均為 NWU。</translation>
    </message>
    <message>
        <location line="+47"/>
        <source>Export cancelled.</source>
        <translation>匯出已取消。</translation>
    </message>
    <message numerus="yes">
        <location line="+10"/>
        <source>%n damaged chunk(s) were skipped</source>
        <translation>
            <numerusform>已略過 %n 個損壞的資料區塊</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>CaptureHeader</name>
    <message>
        <location filename="../core/capture/capture_header.cpp" line="+146"/>
        <source>line %1 of the capture header is not a key=value entry</source>
        <translation>記錄檔檔頭第 %1 行不是「鍵=值」項目</translation>
    </message>
</context>
<context>
    <name>CaptureReader</name>
    <message>
        <location filename="../core/capture/capture_reader.cpp" line="+43"/>
        <source>Cannot open %1: %2</source>
        <translation>無法開啟 %1：%2</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <location line="+66"/>
        <source>not an ImuDesk capture file (it does not start with IMUDCAP1); raw byte dumps are read by &apos;imudesk-cli decode&apos;</source>
        <translation>不是 ImuDesk 記錄檔（開頭不是 IMUDCAP1）；原始位元組傾印請用「imudesk-cli decode」讀取</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>capture format version %1 is newer than this ImuDesk reads (%2); update ImuDesk</source>
        <translation>記錄檔格式版本 %1 比此版 ImuDesk 可讀取的版本（%2）新；請更新 ImuDesk</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the capture header claims %1 bytes (at most %2): the file is damaged</source>
        <translation>記錄檔檔頭宣稱有 %1 位元組（最多 %2）：檔案已損壞</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the file ends inside the capture header: nothing was recorded</source>
        <translation>檔案在記錄檔檔頭內就結束了：沒有記錄任何資料</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the capture header&apos;s CRC does not match: the file is damaged</source>
        <translation>記錄檔檔頭的 CRC 不符：檔案已損壞</translation>
    </message>
    <message>
        <location line="+59"/>
        <location line="+31"/>
        <source>the file ends inside a chunk at offset %1 (recording was interrupted); everything before it was read</source>
        <translation>檔案在偏移量 %1 處的資料區塊內結束（記錄被中斷）；之前的內容已全部讀取</translation>
    </message>
    <message>
        <location line="-21"/>
        <source>damaged chunk at offset %1 (bad framing); skipped</source>
        <translation>偏移量 %1 處的資料區塊已損壞（區塊邊界錯誤）；已略過</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>damaged chunk at offset %1 (bad length); skipped</source>
        <translation>偏移量 %1 處的資料區塊已損壞（長度錯誤）；已略過</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>damaged chunk at offset %1 (CRC mismatch); skipped</source>
        <translation>偏移量 %1 處的資料區塊已損壞（CRC 不符）；已略過</translation>
    </message>
</context>
<context>
    <name>CaptureSource</name>
    <message>
        <location filename="../core/record/capture_source.cpp" line="+46"/>
        <source>%1 cannot be read: %2</source>
        <translation>無法讀取 %1：%2</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 is empty</source>
        <translation>%1 是空檔案</translation>
    </message>
    <message>
        <location line="+108"/>
        <source>No temporary folder to convert %1 in: %2</source>
        <translation>沒有可用於轉換 %1 的臨時資料夾：%2</translation>
    </message>
    <message numerus="yes">
        <location line="-38"/>
        <source>%1 is a vendor CSV: %n row(s) read, times from its pc_counter column</source>
        <translation>
            <numerusform>%1 是廠商 CSV：已讀取 %n 行，時間取自 pc_counter 欄</numerusform>
        </translation>
    </message>
    <message>
        <location line="-54"/>
        <source>%1 is neither an ImuDesk capture nor %2</source>
        <translation>%1 既不是 ImuDesk 記錄檔，也不是%2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 is neither an ImuDesk capture, %2 nor %3</source>
        <translation>%1 既不是 ImuDesk 記錄檔，也不是%2或%3</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>%1 is already an ImuDesk capture</source>
        <translation>%1 已經是 ImuDesk 記錄檔</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>%1 malformed lines in all</source>
        <translation>共 %1 行格式錯誤</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 is a raw byte dump without arrival times: the times shown come from the device&apos;s own clock</source>
        <translation>%1 是原始位元組轉儲，沒有接收時間：顯示的時間取自裝置自身的時鐘</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 is a raw byte dump without arrival times, and nothing in it carries a device time: every time is 0</source>
        <translation>%1 是原始位元組轉儲，沒有接收時間，其中也沒有任何裝置時間：所有時間均為 0</translation>
    </message>
    <message numerus="yes">
        <location line="+4"/>
        <source>The device clock restarted or jumped %n time(s); the times go on across each jump.</source>
        <translation>
            <numerusform>裝置時鐘重啟或跳變了 %n 次；時間在每次跳變處連續延續。</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>CaptureWriter</name>
    <message>
        <location filename="../core/capture/capture_writer.cpp" line="+94"/>
        <source>Cannot create the capture file %1: %2. Choose a folder you can write to.</source>
        <translation>無法建立記錄檔 %1：%2。請選擇可寫入的資料夾。</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Cannot write the capture file %1: %2. Check the free disk space.</source>
        <translation>無法寫入記錄檔 %1：%2。請檢查可用磁碟空間。</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>Recording stopped: the disk cannot keep up (more than %1 MB waiting to be written). Record to a faster disk.</source>
        <translation>記錄已停止：磁碟寫入速度跟不上（超過 %1 MB 等待寫入）。請記錄到速度較快的磁碟。</translation>
    </message>
    <message>
        <location line="+108"/>
        <source>Recording stopped: writing %1 failed (%2). Everything up to that point is in the file; free some disk space and record again.</source>
        <translation>記錄已停止：寫入 %1 失敗（%2）。此前的內容均已寫入檔案；請釋放磁碟空間後重新記錄。</translation>
    </message>
</context>
<context>
    <name>CheckReport</name>
    <message>
        <location filename="../core/verify/gyro_fit.cpp" line="+118"/>
        <source>no still pose</source>
        <translation>沒有靜止姿態</translation>
    </message>
    <message>
        <location filename="../core/verify/dynamic_check.cpp" line="+56"/>
        <location filename="../core/verify/gyro_fit.cpp" line="+27"/>
        <source>needs the accelerometer calibrated from at least 9 still poses</source>
        <translation>需要先以至少 9 個靜止姿態校準加速度計</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>needs a still pose with the module&apos;s attitude to start from</source>
        <translation>需要一個帶有模組姿態輸出的靜止姿態作為起點</translation>
    </message>
    <message>
        <location line="+67"/>
        <source>the module did not move enough between the poses (%1 s, %2° turned; %3 s and %4° needed)</source>
        <translation>模組在靜止姿態之間運動不足（運動 %1 s，轉過 %2°；需要 %3 s 和 %4°）</translation>
    </message>
    <message>
        <location line="+55"/>
        <source>the module&apos;s attitude follows the reference by more than %1 ms or not at all</source>
        <translation>模組姿態落後參考超過 %1 ms，或根本不跟隨參考</translation>
    </message>
    <message>
        <location filename="../core/verify/gyro_fit.cpp" line="+27"/>
        <source>needs at least 3 turns of more than 20° between still poses (found %1)</source>
        <translation>靜止姿態之間需要至少 3 次超過 20° 的轉動（找到 %1 次）</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the turns between poses do not pin the gyro&apos;s scale: turn it about each axis while that axis is level</source>
        <translation>姿態之間的轉動不足以確定陀螺儀的標度：請在各軸水平時繞該軸轉動模組</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>the turns between poses do not pin the gyro&apos;s axes (at least 6 turns of more than 20°, about every axis, are needed; found %1)</source>
        <translation>姿態之間的轉動不足以確定陀螺儀的軸向（需要至少 6 次超過 20° 且涵蓋各軸的轉動；找到 %1 次）</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>the turns between poses did not turn the module about its %1 axis enough: turn it about each axis while that axis is level</source>
        <translation>姿態之間的轉動中，模組繞其 %1 軸轉動不足：請在每個軸保持水平時繞該軸轉動模組</translation>
    </message>
    <message>
        <location filename="../core/verify/module_check.cpp" line="+71"/>
        <source>pass</source>
        <translation>通過</translation>
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
        <translation>無法判定</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>%1: %2 ± %3 %4%5 (95 %), pass at most %6, fail above %7: %8</source>
        <translation>%1：%2 ± %3 %4%5（95 %），不超過 %6 為通過，超過 %7 為不合格：%8</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>%1: cannot judge, %2</source>
        <translation>%1：無法判定，%2</translation>
    </message>
    <message>
        <location line="+40"/>
        <source>hold the module still for 3 s in each of at least %1 orientations (every face up and down, then between them)</source>
        <translation>請在至少 %1 個朝向上各讓模組靜止 3 s（每個面分別朝上和朝下，再加上介於它們之間的朝向）</translation>
    </message>
    <message>
        <location line="+25"/>
        <location line="+10"/>
        <source>no still pose: %1</source>
        <translation>沒有靜止姿態：%1</translation>
    </message>
    <message>
        <location line="-8"/>
        <source>%1 distinct still poses, %2 needed: %3</source>
        <translation>只有 %1 個不同的靜止姿態，需要 %2 個：%3</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the poses do not pin the accelerometer&apos;s errors: %1</source>
        <translation>這些姿態不足以確定加速度計的誤差：%1</translation>
    </message>
    <message>
        <location line="+45"/>
        <source>accelerometer bias</source>
        <translation>加速度計零偏</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>accelerometer scale error</source>
        <translation>加速度計標度誤差</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>accelerometer misalignment</source>
        <translation>加速度計軸間失準</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>gyro bias</source>
        <translation>陀螺儀零偏</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>gyro scale error</source>
        <translation>陀螺儀標度誤差</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>gyro misalignment</source>
        <translation>陀螺儀軸間失準</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>roll error</source>
        <translation>橫滾誤差</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>pitch error</source>
        <translation>俯仰誤差</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>heading error</source>
        <translation>航向誤差</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>attitude error while moving (RMS)</source>
        <translation>運動中的姿態誤差（RMS）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>attitude lag</source>
        <translation>姿態延遲</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>the bench&apos;s gravity was not given: standard gravity (9.80665 m/s²) assumed, its uncertainty (±0.3 %) is in the scale figures; give --gravity or --latitude and --height</source>
        <translation>未給出測試台處的重力加速度：已按標準重力（9.80665 m/s²）計算，其不確定度（±0.3 %）已計入標度的數值；請給出 --gravity，或 --latitude 和 --height</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>a hard iron of %1 µT (the poses&apos; fields off centre) was removed for the heading reference: calibrate the magnetometer</source>
        <translation>為得到航向參考，已扣除 %1 µT 的硬鐵（各姿態的磁場偏離中心）：請校準磁力計</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>pose at %1 s set aside for the heading: %2</source>
        <translation>%1 s 處的姿態已從航向判定中剔除：%2</translation>
    </message>
    <message>
        <location filename="../core/verify/pose_attitude.cpp" line="+98"/>
        <source>needs the accelerometer calibrated from at least 9 still poses: an uncalibrated one is no reference for the tilt</source>
        <translation>需要先以至少 9 個靜止姿態校準加速度計：未校準的加速度計不能作為傾角的參考</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>pitch %1°: roll and heading have no meaning near ±90°</source>
        <translation>俯仰角 %1°：在 ±90° 附近，橫滾和航向沒有意義</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>needs at least 3 still poses with the module&apos;s attitude and a pitch within ±%1° (found %2)</source>
        <translation>需要至少 3 個帶有模組姿態輸出、且俯仰角在 ±%1° 以內的靜止姿態（找到 %2 個）</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>needs at least 3 still poses with a magnetometer, the module&apos;s attitude and a pitch within ±%1° (found %2)</source>
        <translation>需要至少 3 個帶有磁力計資料和模組姿態輸出、且俯仰角在 ±%1° 以內的靜止姿態（找到 %2 個）</translation>
    </message>
    <message>
        <location line="+47"/>
        <source>field %1 µT, %2 % from the other poses&apos;: a magnetic disturbance here</source>
        <translation>磁場 %1 µT，與其他姿態的磁場相差 %2 %：此處有磁干擾</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>field inclination %1°, %2° from the other poses&apos;: a magnetic disturbance here</source>
        <translation>磁傾角 %1°，與其他姿態的磁傾角相差 %2°：此處有磁干擾</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>the magnetic field disagreed between the poses (%1 of %2 set aside): calibrate the magnetometer, move away from steel and motors, and record again</source>
        <translation>各姿態的磁場不一致（%2 個中剔除了 %1 個）：請校準磁力計，遠離鋼鐵和馬達，然後重新錄製</translation>
    </message>
    <message>
        <location filename="../core/verify/compass_check.cpp" line="+106"/>
        <source>the compass was not held still for %1 s at the bearings %2°: turn it to each marked bearing of a level compass rose and hold it there</source>
        <translation>羅盤未在方位 %2° 處靜止保持 %1 s：請在水平的羅經盤上將它依次轉到每個標記方位並保持不動</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>heading error: cannot judge, %1</source>
        <translation>航向誤差：無法判定，%1</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>%1: %2 ± %3 ° (95 %), pass at most %4, fail above %5: %6</source>
        <translation>%1：%2 ± %3 °（95 %），不超過 %4 為通過，超過 %5 為不合格：%6</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>heading error at %1°, the worst bearing</source>
        <translation>%1° 處的航向誤差（最差方位）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>heading offset, mean of the bearings</source>
        <translation>航向偏移（各方位平均）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>pitch on the level rose</source>
        <translation>水平羅經盤上的俯仰</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>roll on the level rose</source>
        <translation>水平羅經盤上的橫滾</translation>
    </message>
</context>
<context>
    <name>CompassPoseTracker</name>
    <message>
        <location filename="../core/calib/compass_pose_tracker.cpp" line="+102"/>
        <source>Automatic 12-point</source>
        <translation>自動 12 點</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Manual</source>
        <translation>手動</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Automatic all-orientation</source>
        <translation>自動全姿態</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>12-point small tilt</source>
        <translation>12 點小傾角</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Planar</source>
        <translation>平面</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Turn the compass, together with everything mounted with it, to each of the 12 poses shown; it collects a point by itself near each one. Needs pitch beyond 45 deg and roll beyond 30 deg.</source>
        <translation>將羅盤連同與其一起安裝的所有物件依序轉到圖示的 12 個姿態；接近每個姿態時會自動採集一個點。俯仰角需超過 45 deg，橫滾角需超過 30 deg。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Turn the compass to the poses it will be used in and collect a point at each (at least 12); spread the headings evenly.</source>
        <translation>將羅盤轉到實際使用時的各個姿態，並在每個姿態採集一個點（至少 12 個）；航向角應均勻分佈。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Start level. Turn 2-3 times about the vertical axis (10-15 s per turn, speeding up and slowing down), then 1-2 times about X and Y (about 10 s per turn), then at random so that every orientation is reached. Up to 96 points.</source>
        <translation>從水平位置開始。先繞垂直軸轉 2-3 圈（每圈 10-15 s，時快時慢），再繞 X 軸和 Y 軸各轉 1-2 圈（每圈約 10 s），然後隨意轉動，使每個姿態都轉到。最多 96 個點。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>For roll below 5 deg: keep it nearly level in roll and turn to the 12 headings and pitches shown (pitch beyond 45 deg).</source>
        <translation>適用於橫滾角小於 5 deg 的情況：橫滾方向保持接近水平，轉到圖示的 12 個航向角和俯仰角（俯仰角超過 45 deg）。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Place the compass level (pitch and roll below 2 deg) and turn it one full circle slowly and evenly. Up to 12 points.</source>
        <translation>將羅盤水平放置（俯仰角和橫滾角小於 2 deg），緩慢均勻地旋轉一整圈。最多 12 個點。</translation>
    </message>
    <message>
        <location line="+80"/>
        <source>%1 points collected, at least %2 needed.</source>
        <translation>已採集 %1 個點，至少需要 %2 個。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 points collected: you can save the calibration.</source>
        <translation>已採集 %1 個點：可以儲存校準。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Point %1: heading %2 deg, pitch %3..%4 deg, roll %5..%6 deg</source>
        <translation>第 %1 點：航向角 %2 deg，俯仰角 %3..%4 deg，橫滾角 %5..%6 deg</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>All %1 points collected: save the calibration.</source>
        <translation>%1 個點已全部採集：請儲存校準。</translation>
    </message>
</context>
<context>
    <name>ConfigProfile</name>
    <message>
        <location filename="../core/settings/config_profile.cpp" line="+55"/>
        <source>the profile is larger than %1 KiB: not an ImuDesk profile</source>
        <translation>設定檔大於 %1 KiB：不是 ImuDesk 設定檔</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the profile is not valid JSON (%1 at byte %2)</source>
        <translation>設定檔不是有效的 JSON（位元組 %2 處：%1）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the profile must be a JSON object</source>
        <translation>設定檔必須是 JSON 物件</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>not an ImuDesk profile (&quot;format&quot; must be &quot;imudesk-profile&quot;)</source>
        <translation>不是 ImuDesk 設定檔（&quot;format&quot; 必須為 &quot;imudesk-profile&quot;）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>profile version %1 is not supported (this ImuDesk reads version %2)</source>
        <translation>不支援設定檔版本 %1（此版 ImuDesk 讀取版本 %2）</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&quot;device&quot; must be an object</source>
        <translation>&quot;device&quot; 必須是物件</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>&quot;settings&quot; must be an object of &quot;KEY&quot;: &quot;VALUE&quot;</source>
        <translation>&quot;settings&quot; 必須是 &quot;KEY&quot;: &quot;VALUE&quot; 形式的物件</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>too many settings (%1)</source>
        <translation>設定項過多（%1）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>unknown setting &apos;%1&apos; in the profile</source>
        <translation>設定檔中有未知的設定項「%1」</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the value of %1 must be a string</source>
        <translation>%1 的值必須是字串</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>cannot write %1: %2</source>
        <translation>無法寫入 %1：%2</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>cannot read %1: %2</source>
        <translation>無法讀取 %1：%2</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 is larger than %2 KiB: not an ImuDesk profile</source>
        <translation>%1 大於 %2 KiB：不是 ImuDesk 設定檔</translation>
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
        <translation>無法寫入 %1：%2</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>Writing %1 failed: %2. Check the free disk space.</source>
        <translation>寫入 %1 失敗：%2。請檢查磁碟剩餘空間。</translation>
    </message>
</context>
<context>
    <name>FamilyUi</name>
    <message>
        <location filename="../ui/workspace/family_ui.cpp" line="+22"/>
        <source>Disconnect first, then connect to %1.</source>
        <translation>請先中斷連線，再連線 %1。</translation>
    </message>
    <message>
        <location line="+43"/>
        <source>Nothing was opened.</source>
        <translation>沒有開啟任何連線。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 answered, but ImuDesk has no view for its family.</source>
        <translation>%1 有回應，但 ImuDesk 沒有適用於該裝置系列的檢視。</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Disconnect first, then connect again.</source>
        <translation>請先中斷連線，再重新連線。</translation>
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
            <numerusform>已略過 %n 個損壞的資料區塊</numerusform>
        </translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 holds no IMU frames to analyse</source>
        <translation>%1 中沒有可分析的 IMU 資料幀</translation>
    </message>
</context>
<context>
    <name>GyroScaleRun</name>
    <message>
        <location filename="../core/calib/gyro_scale_run.cpp" line="+186"/>
        <source>turn %1 ended at %2 deg, not within %3 deg of %4 deg</source>
        <translation>第 %1 次轉動停在 %2 deg，與 %4 deg 相差超過 %3 deg</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>turn %1 averaged %2 deg/s, outside %3..%4 deg/s</source>
        <translation>第 %1 次轉動平均 %2 deg/s，超出 %3..%4 deg/s</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>turn %1 paused on the way</source>
        <translation>第 %1 次轉動中途停頓</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>turn %1 was uneven (rate varied by %2 %)</source>
        <translation>第 %1 次轉動不均勻（轉速變化 %2 %）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the module is tilted %1 deg: place it level</source>
        <translation>模組傾斜 %1 deg：請水平放置</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Run not finished (%1 of %2 turns done).</source>
        <translation>本輪未完成（已完成 %1/%2 次轉動）。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Estimated gyro scale error %1 % (bias %2 deg/s, output rate %3 Hz).</source>
        <translation>估計陀螺儀標度誤差 %1 %（零偏 %2 deg/s，輸出速率 %3 Hz）。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Estimated gyro scale error %1 %, but the run was not clean: %2. Repeat it.</source>
        <translation>估計陀螺儀標度誤差 %1 %，但本輪操作不合格：%2。請重做。</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Place the module level on a flat, steady surface, then start.</source>
        <translation>將模組水平放在平整穩固的表面上，然後開始。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Hold the module still (%1 of %2 s).</source>
        <translation>請保持模組靜止（%1/%2 s）。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Turn the module %1 deg (%2 turns) at an even 20-100 deg/s, in either direction.</source>
        <translation>以 20-100 deg/s 的均勻轉速將模組轉動 %1 deg（%2 圈），方向不限。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Now turn it back the other way, %1 deg, to the same mark.</source>
        <translation>現在反方向轉回 %1 deg，回到同一標記。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Stop now: on the mark.</source>
        <translation>立即停止：已到標記。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Too far: %1 deg past the target. Stop and repeat the run.</source>
        <translation>轉過頭：超出目標 %1 deg。請停止並重做。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Keep turning, a little faster: %1 deg to go.</source>
        <translation>繼續轉動，稍快一些：還剩 %1 deg。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Keep turning, a little slower: %1 deg to go.</source>
        <translation>繼續轉動，稍慢一些：還剩 %1 deg。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Keep turning evenly: %1 deg to go.</source>
        <translation>繼續均勻轉動：還剩 %1 deg。</translation>
    </message>
</context>
<context>
    <name>HEC495</name>
    <message>
        <location filename="../core/protocol/can/hec495_can.cpp" line="+266"/>
        <source>node ID = %1</source>
        <translation>節點 ID = %1</translation>
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
        <translation>啟動 PDO</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>stop PDO</source>
        <translation>停止 PDO</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PDO rate = %1 Hz</source>
        <translation>PDO 頻率 = %1 Hz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>work mode = 0x%1</source>
        <translation>工作模式 = 0x%1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>object 0x%1 = %2</source>
        <translation>物件 0x%1 = %2</translation>
    </message>
</context>
<context>
    <name>HeadingCheck</name>
    <message>
        <location filename="../core/calib/heading_check.cpp" line="+138"/>
        <source>Passed: %1 deg turned level, the heading followed without a jump (largest step %2 deg).</source>
        <translation>通過：水平轉動了 %1°，航向平滑跟隨，沒有跳變（最大步長 %2°）。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The heading jumped by %1 deg while the module was level and the field steady: the heading does not follow the calibration. Calibrate again (chapter 9.31).</source>
        <translation>模組水平且磁場穩定時航向跳變了 %1°：航向不符合校準。請重新校準（第 9.31 章）。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Keep the module level while you turn it: it is tilted by %1 deg, at most %2 deg is judged. The heading of a tilted module also moves with the tilt, so the check cannot judge it (%3 of %4 deg turned level so far).</source>
        <translation>轉動時請保持模組水平：目前傾斜 %1°，最多 %2° 才會被判定。傾斜模組的航向也會隨傾斜變化，因此無法據此判定（目前已水平轉動 %3°/%4°）。</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>The field is disturbed here (|B| %1 % off the level turn&apos;s): iron, a magnet or a current nearby. The check cannot judge the heading in a disturbed field; move away from it and turn on.</source>
        <translation>此處磁場受到干擾（|B| 偏離水平轉動時的值 %1 %）：附近有鐵、磁鐵或電流。磁場受擾時無法判定航向；請遠離干擾源後繼續轉動。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Keep turning, level and slowly: %1 of %2 deg turned.</source>
        <translation>請保持水平、緩慢地繼續轉動：已轉動 %1°/%2°。</translation>
    </message>
</context>
<context>
    <name>Hec495SerialKind</name>
    <message>
        <location filename="../core/links/hec495_serial_kind.cpp" line="+48"/>
        <source>an HEC495 compass</source>
        <translation>HEC495 羅盤</translation>
    </message>
    <message>
        <location line="+40"/>
        <source>The simulated compass could not start: %1</source>
        <translation>模擬羅盤無法啟動：%1</translation>
    </message>
</context>
<context>
    <name>Hec495SerialUi</name>
    <message>
        <location filename="../ui/families/hec495_serial_ui.cpp" line="+22"/>
        <source>Simulated HEC495</source>
        <translation>模擬 HEC495</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>HEC495 on %1</source>
        <translation>%1 上的 HEC495</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Simulated HEC495 compass</source>
        <translation>模擬 HEC495 羅盤</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>Compass</source>
        <translation>羅盤</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Compass settings</source>
        <translation>羅盤設定</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Switch the output to all data</source>
        <translation>將輸出切換為全部資料</translation>
    </message>
</context>
<context>
    <name>HipnucRawDumpImport</name>
    <message>
        <location filename="../core/decode/hipnuc_file_import.cpp" line="+186"/>
        <source>a raw dump of what a module sent (HiPNUC frames or NMEA sentences in its first %1 KiB)</source>
        <translation>模組傳送內容的原始傾印（前 %1 KiB 中含 HiPNUC 幀或 NMEA 語句）</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1 cannot be read: %2</source>
        <translation>無法讀取 %1：%2</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Reading %1 failed: %2</source>
        <translation>讀取 %1 失敗：%2</translation>
    </message>
</context>
<context>
    <name>HipnucSerialKind</name>
    <message>
        <location filename="../core/links/hipnuc_serial_kind.cpp" line="+42"/>
        <source>a HiPNUC module</source>
        <translation>HiPNUC 模組</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>The simulated device could not start: %1</source>
        <translation>模擬裝置無法啟動：%1</translation>
    </message>
</context>
<context>
    <name>HipnucSerialUi</name>
    <message>
        <location filename="../ui/families/hipnuc_serial_ui.cpp" line="+38"/>
        <location line="+9"/>
        <source>Simulated %1 (firmware %2)</source>
        <translation>模擬 %1（韌體 %2）</translation>
    </message>
</context>
<context>
    <name>HipnucVendorCsvImport</name>
    <message>
        <location filename="../core/decode/hipnuc_file_import.cpp" line="-82"/>
        <source>a vendor CSV (first line &quot;HI91,...&quot;)</source>
        <translation>廠商 CSV（首行為「HI91,...」）</translation>
    </message>
</context>
<context>
    <name>HipnucWrites</name>
    <message>
        <location filename="../core/protocol/modbus/hipnuc_writes.cpp" line="+107"/>
        <source>save the configuration to flash</source>
        <translation>將配置儲存到快閃記憶體</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>restore the factory settings</source>
        <translation>恢復出廠設定</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>reset the module</source>
        <translation>重設模組</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>set the baud rate to %1</source>
        <translation>將波特率設為 %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>set the node ID to %1</source>
        <translation>將節點 ID 設為 %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>switch to 9-axis mode</source>
        <translation>切換到 9 軸模式</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>switch to 6-axis mode</source>
        <translation>切換到 6 軸模式</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>cancel the levelling (value 5)</source>
        <translation>取消調平（值 5）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>level once (value 2, as the manual&apos;s worked example sends it; its register table lists 3)</source>
        <translation>執行一次調平（值 2，與手冊範例傳送的一致；手冊暫存器表列出的是 3）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>level once (value 3, as the manual&apos;s register table defines it)</source>
        <translation>執行一次調平（值 3，依手冊暫存器表的定義）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>set the mounting (URFR value %1)</source>
        <translation>設定安裝方式（URFR 值 %1）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>write %1 to register 0x%2</source>
        <translation>將 %1 寫入暫存器 0x%2</translation>
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
        <translation>檔案大小為 %1 位元組，超過韌體檔案上限 %2 位元組</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>data after the end-of-file record of line %1; the file is damaged</source>
        <translation>第 %1 行的檔案結束記錄之後還有資料；檔案已損壞</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>a record must start with &apos;:&apos;; this is not an Intel HEX file</source>
        <translation>記錄必須以「:」開頭；這不是 Intel HEX 檔案</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the record is too short or has an odd number of hex digits; the file is truncated or damaged</source>
        <translation>記錄太短或十六進位數字個數為奇數；檔案被截斷或已損壞</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>&apos;%1&apos; is not a hex digit</source>
        <translation>「%1」不是十六進位數字</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the record says %1 data bytes but holds %2; the file is truncated or damaged</source>
        <translation>記錄標示有 %1 個資料位元組，實際為 %2 個；檔案被截斷或已損壞</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>checksum error (record says %1, bytes give %2); the file is damaged</source>
        <translation>校驗和錯誤（記錄標示 %1，按位元組計算為 %2）；檔案已損壞</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>the record runs past the 4 GiB address space</source>
        <translation>記錄超出 4 GiB 位址空間</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>an end-of-file record must have no data and address 0</source>
        <translation>檔案結束記錄必須沒有資料且位址為 0</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>an extended address record must have 2 data bytes and address 0</source>
        <translation>擴充位址記錄必須有 2 個資料位元組且位址為 0</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>a start address record must have 4 data bytes and address 0</source>
        <translation>起始位址記錄必須有 4 個資料位元組且位址為 0</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>unknown record type %1 (Intel HEX has types 00 to 05)</source>
        <translation>未知的記錄類型 %1（Intel HEX 的類型為 00 到 05）</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the file is empty; choose the firmware&apos;s .hex file</source>
        <translation>檔案為空；請選擇韌體的 .hex 檔案</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the file ends without an end-of-file record (type 01); it is truncated, download it again</source>
        <translation>檔案缺少檔案結束記錄（類型 01）就結束了；檔案被截斷，請重新下載</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the file holds no data records</source>
        <translation>檔案中沒有資料記錄</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the record writes %1, which line %2 already wrote (overlapping records); the file is damaged</source>
        <translation>該記錄寫入 %1，而第 %2 行已寫入此處（記錄重疊）；檔案已損壞</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>the image spans %1 bytes from %2, more than %3; the addresses are wrong or this is not a firmware for this device</source>
        <translation>映像從 %2 起跨越 %1 位元組，超過 %3；位址錯誤，或這不是本裝置的韌體</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>the file is empty; choose the firmware&apos;s .bin file</source>
        <translation>檔案為空；請選擇韌體的 .bin 檔案</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the file is %1 bytes, more than %2; this is not a firmware for this device</source>
        <translation>檔案大小為 %1 位元組，超過 %2；這不是本裝置的韌體</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the image runs past the 4 GiB address space; check the start address</source>
        <translation>映像超出 4 GiB 位址空間；請檢查起始位址</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>cannot read %1: %2</source>
        <translation>無法讀取 %1：%2</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 is %2 bytes, more than the %3 bytes a firmware file may have</source>
        <translation>%1 大小為 %2 位元組，超過韌體檔案上限 %3 位元組</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>a .bin file has no address: give its start address (e.g. 0x8000)</source>
        <translation>.bin 檔案沒有位址資訊：請指定其起始位址（例如 0x8000）</translation>
    </message>
</context>
<context>
    <name>J1939</name>
    <message>
        <location filename="../core/protocol/can/j1939_config.cpp" line="+104"/>
        <source>PGN %1 interval</source>
        <translation>PGN %1 間隔</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>write %1 = %2 ms</source>
        <translation>寫入 %1 = %2 ms</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>save configuration</source>
        <translation>儲存配置</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>factory defaults</source>
        <translation>恢復出廠設定</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>reset</source>
        <translation>重設</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>command register</source>
        <translation>指令暫存器</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>trigger PGN %1</source>
        <translation>觸發 PGN %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>trigger</source>
        <translation>觸發</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>CAN baud code</source>
        <translation>CAN 波特率代碼</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>node ID</source>
        <translation>節點 ID</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>output enable</source>
        <translation>輸出啟用</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>inclinometer X sign</source>
        <translation>傾角儀 X 軸符號</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>inclinometer Y sign</source>
        <translation>傾角儀 Y 軸符號</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>attitude reset</source>
        <translation>姿態重設</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>firmware version</source>
        <translation>韌體版本</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>register 0x%1</source>
        <translation>暫存器 0x%1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>write %1 = %2 (status %3)</source>
        <translation>寫入 %1 = %2（狀態 %3）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>read %1 -&gt; %2 (status %3)</source>
        <translation>讀取 %1 -&gt; %2（狀態 %3）</translation>
    </message>
</context>
<context>
    <name>KbootClient</name>
    <message>
        <location filename="../core/firmware/kboot_client.cpp" line="+58"/>
        <source>%1: only damaged bytes arrived (%2 bytes skipped, %3 CRC errors); the line is noisy or the baud is wrong. Run the update again</source>
        <translation>%1：只收到損壞的位元組（略過 %2 位元組，%3 個 CRC 錯誤）；線路雜訊大或波特率錯誤。請重新執行更新</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: the bootloader did not answer; check the cable and power, then run the update again</source>
        <translation>%1：開機載入程式沒有回應；請檢查線纜和電源，然後重新執行更新</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>no bootloader answered %1 pings; check the port and baud rate, power-cycle the module and run the update again</source>
        <translation>%1 次連線偵測均無開機載入程式回應；請檢查串列埠和波特率，將模組斷電重啟後重新執行更新</translation>
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
        <translation>%1 無 ACK</translation>
    </message>
    <message>
        <location line="-128"/>
        <source>the bootloader aborted %1</source>
        <translation>開機載入程式中止了 %1</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the bootloader refused %1 %2 times (NAK: damaged on the way); check the cable</source>
        <translation>開機載入程式拒絕 %1 達 %2 次（NAK：傳輸途中損壞）；請檢查線纜</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>response to command 0x%1</source>
        <translation>對指令 0x%1 的回應</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>no %1 within %2 ms</source>
        <translation>%2 ms 內未收到 %1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>malformed %1</source>
        <translation>%1 格式錯誤</translation>
    </message>
    <message>
        <location line="+8"/>
        <location line="+20"/>
        <source>the bootloader answered command 0x%1 instead of 0x%2</source>
        <translation>開機載入程式回應的是指令 0x%1，而非 0x%2</translation>
    </message>
    <message>
        <location line="-14"/>
        <location line="+21"/>
        <source>the bootloader refused command 0x%1: %2</source>
        <translation>開機載入程式拒絕指令 0x%1：%2</translation>
    </message>
    <message>
        <location line="-14"/>
        <source>unexpected response 0x%1 to command 0x%2</source>
        <translation>指令 0x%2 收到非預期的回應 0x%1</translation>
    </message>
    <message>
        <location line="+69"/>
        <source>data packet %1 (bytes %2..%3 at 0x%4)</source>
        <translation>資料封包 %1（位元組 %2..%3，位址 0x%4）</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>the bootloader aborted the transfer at %1: %2</source>
        <translation>開機載入程式在 %1 處中止傳輸：%2</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the bootloader ended the transfer at %1: %2</source>
        <translation>開機載入程式在 %1 處結束傳輸：%2</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>data packet %1 was refused %2 times (NAK); the line is damaging data. Check the cable and run the update again</source>
        <translation>資料封包 %1 被拒絕 %2 次（NAK）；線路正在損壞資料。請檢查線纜並重新執行更新</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>cancelled after %1 of %2 bytes</source>
        <translation>在 %1 / %2 位元組後取消</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>the bootloader offers %1 bytes instead of %2</source>
        <translation>開機載入程式提供 %1 位元組，而非 %2</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>reading back stopped after %1 of %2 bytes</source>
        <translation>回讀在 %1 / %2 位元組後停止</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>cancelled while reading back</source>
        <translation>回讀時已取消</translation>
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
        <translation>操作失敗</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the target is read-only</source>
        <translation>目標為唯讀</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a value is out of range</source>
        <translation>數值超出範圍</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>an argument is invalid</source>
        <translation>參數無效</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the bootloader timed out</source>
        <translation>開機載入程式逾時</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no transfer is in progress</source>
        <translation>目前沒有進行中的傳輸</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the length is not a multiple of the flash unit</source>
        <translation>長度不是快閃記憶體單元的整數倍</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the address or length is not aligned to a flash sector</source>
        <translation>位址或長度未對齊快閃記憶體磁區</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the address is outside the flash</source>
        <translation>位址超出快閃記憶體範圍</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>flash access error</source>
        <translation>快閃記憶體存取錯誤</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the region is protected (e.g. the bootloader)</source>
        <translation>該區域受保護（例如開機載入程式）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the flash command failed</source>
        <translation>快閃記憶體指令失敗</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unknown flash property</source>
        <translation>未知的快閃記憶體屬性</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>wrong erase key</source>
        <translation>抹除金鑰錯誤</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the region is execute-only</source>
        <translation>該區域為僅執行</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the bootloader does not know this command</source>
        <translation>開機載入程式不認識此指令</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the command is refused while the chip is secured</source>
        <translation>晶片處於安全鎖定狀態時拒絕此指令</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the data phase was aborted</source>
        <translation>資料階段已中止</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>ping error</source>
        <translation>連線偵測錯誤</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no response</source>
        <translation>無回應</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no response expected</source>
        <translation>不需要回應</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the bootloader does not support this command</source>
        <translation>開機載入程式不支援此指令</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the address range is invalid for this memory</source>
        <translation>位址範圍對此記憶體無效</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>reading the memory failed</source>
        <translation>讀取記憶體失敗</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>writing the memory failed</source>
        <translation>寫入記憶體失敗</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the flash was not erased before writing</source>
        <translation>寫入前快閃記憶體未抹除</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the bootloader does not know this property</source>
        <translation>開機載入程式不認識此屬性</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the property is read-only</source>
        <translation>該屬性為唯讀</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>invalid property value</source>
        <translation>屬性值無效</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>application CRC check passed</source>
        <translation>應用程式 CRC 檢查通過</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>application CRC check failed</source>
        <translation>應用程式 CRC 檢查失敗</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>application CRC check inactive</source>
        <translation>應用程式 CRC 檢查未啟用</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>application CRC check invalid</source>
        <translation>應用程式 CRC 檢查無效</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>application CRC check range out of range</source>
        <translation>應用程式 CRC 檢查範圍超出界限</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no ping response</source>
        <translation>連線偵測無回應</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>invalid packet type</source>
        <translation>封包類型無效</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>packet CRC error</source>
        <translation>封包 CRC 錯誤</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no command response</source>
        <translation>指令無回應</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unknown status %1</source>
        <translation>未知狀態 %1</translation>
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
        <translation>1. 檢查校準位置的磁場：保持模組靜止並讀取 |B|；20-60 µT 為正常。低於 20 µT 或高於 60 µT 表示附近有磁性物體：遠離它或更換位置。
2. 檢查旋轉動作：繞每個軸至少旋轉 360 deg，速度 20-100 deg/s，中途不要停頓。
3. 檢查空間磁場干擾：在同一位置、不同朝向測量 |B|。若變化超過 10 µT，請更換位置或改用 6 軸模式。
旋轉時保持模組位置不變，並將模組與所有固聯物體作為整體一起校準。</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Starting the calibration on the device.</source>
        <translation>正在啟動裝置上的校準。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>This firmware calibrates in the background in 9-axis mode: turn the module slowly through as many orientations as you can.</source>
        <translation>此韌體在 9 軸模式下於背景校準：請緩慢轉動模組，盡可能經過更多姿態。</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>The device did not finish the calibration within %1 s.</source>
        <translation>裝置未在 %1 s 內完成校準。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Calibrating: turn the module slowly about every axis.</source>
        <translation>校準中：請繞每個軸緩慢轉動模組。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The device did not answer CONFIG MCAL START: its firmware is older than 1.7.0 or the link is down.</source>
        <translation>裝置未回應 CONFIG MCAL START：其韌體版本低於 1.7.0，或連線已中斷。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The device refused CONFIG MCAL START (%1): it may have no magnetometer.</source>
        <translation>裝置拒絕 CONFIG MCAL START（%1）：它可能沒有磁力計。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The device stopped answering %1 (%2 times in a row).</source>
        <translation>裝置已停止回應 %1（連續 %2 次）。</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>LOG MAGCONFIG gave no MB line.</source>
        <translation>LOG MAGCONFIG 未傳回 MB 行。</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+5"/>
        <source>LOG MAGCONFIG gave an unreadable MB line: %1</source>
        <translation>LOG MAGCONFIG 傳回無法解讀的 MB 行：%1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The device calibrated itself: bias %1, %2, %3 µT.</source>
        <translation>裝置已自行完成校準：偏置 %1, %2, %3 µT。</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>LOG MCAL STAT gave no STAT line.</source>
        <translation>LOG MCAL STAT 未傳回 STAT 行。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The device is idle: the calibration stopped (was the device restarted?). Start again.</source>
        <translation>裝置處於閒置狀態：校準已停止（裝置是否已重新啟動？）。請重新開始。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Calibrating (%1 %): keep turning the module slowly about every axis.</source>
        <translation>校準中（%1 %）：請繼續繞每個軸緩慢轉動模組。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Verifying the result: hold the module still.</source>
        <translation>正在驗證結果：請保持模組靜止。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The device reports the calibration done.</source>
        <translation>裝置回報校準已完成。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The device reports the calibration failed (STAT=4).</source>
        <translation>裝置回報校準失敗（STAT=4）。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>LOG MCAL STAT gave an unknown state %1.</source>
        <translation>LOG MCAL STAT 傳回未知狀態 %1。</translation>
    </message>
</context>
<context>
    <name>MagCalResult</name>
    <message>
        <location filename="../core/calib/mag_cal_result.cpp" line="+71"/>
        <source>Pass</source>
        <translation>通過</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Warning</source>
        <translation>警告</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Fail</source>
        <translation>失敗</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Refused</source>
        <translation>已拒絕</translation>
    </message>
</context>
<context>
    <name>MagCalibrator</name>
    <message>
        <location filename="../core/calib/mag_calibrator.cpp" line="+90"/>
        <source>Only %1 usable samples; a full calibration needs at least %2. Keep turning the module slowly.</source>
        <translation>僅有 %1 個可用樣本；完整校準至少需要 %2 個。請繼續緩慢轉動模組。</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>The samples lie in one plane (the module turned about one axis only), so a full 3-D calibration cannot be computed. Turn the module about its other axes too, or use the 2-D (planar) calibration, which is valid for level operation only.</source>
        <translation>樣本都位於同一平面（模組只繞一個軸轉動），無法計算完整的三維校準。請讓模組也繞其他軸轉動，或使用二維（平面）校準，但二維校準僅適用於水平使用。</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Only %1 % of the field directions are covered (at least %2 % are needed before a fit is tried). %3.</source>
        <translation>僅覆蓋了 %1 % 的磁場方向（嘗試擬合前至少需要 %2 %）。%3。</translation>
    </message>
    <message>
        <location line="+6"/>
        <location line="+9"/>
        <location line="+217"/>
        <source>A hard-iron-only fit (soft iron kept from before) is possible.</source>
        <translation>可以只擬合硬鐵（保留先前的軟鐵參數）。</translation>
    </message>
    <message>
        <location line="-220"/>
        <source>No ellipsoid fits these samples, which cover only part of the sphere. %1, then fit again.</source>
        <translation>這些樣本只覆蓋了球面的一部分，沒有橢球能擬合它們。%1，然後重新擬合。</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>The samples do not describe an ellipsoid (strong interference or a moving magnet nearby). Move away from iron and electronics and calibrate again.</source>
        <translation>樣本無法構成橢球（附近有強干擾或移動的磁鐵）。請遠離鐵件和電子裝置後重新校準。</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Only %1 usable samples; the hard-iron fit needs at least %2.</source>
        <translation>僅有 %1 個可用樣本；硬鐵擬合至少需要 %2 個。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The samples are too close to a plane (eigenvalue ratio %1, at most %2) even for a hard-iron fit. Tilt the module more while turning it.</source>
        <translation>樣本過於接近同一平面（特徵值比 %1，最大 %2），連硬鐵擬合也無法進行。轉動時請讓模組傾斜更多。</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>The hard-iron fit found no solution: check that the samples come from the magnetometer in µT.</source>
        <translation>硬鐵擬合無解：請檢查樣本是否來自磁力計且單位為 µT。</translation>
    </message>
    <message>
        <location line="+97"/>
        <source>field strength %1 µT is not the earth&apos;s field (%2..%3 µT)</source>
        <translation>磁場強度 %1 µT 不是地磁場（%2..%3 µT）</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>the predicted heading error of a level module, %1 deg, is above %2 deg (hard iron +-%3 µT)</source>
        <translation>模組水平時的預測航向誤差 %1 deg 超過 %2 deg（硬鐵 +-%3 µT）</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the heading error of a level module stays below %1 deg only 19 times in 20 (over %2 deg)</source>
        <translation>模組水平時的航向誤差只有 20 次中 19 次低於 %1 deg（超過 %2 deg）</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>field strength %1 µT is outside the normal %2..%3 µT: move away from magnetic objects</source>
        <translation>磁場強度 %1 µT 超出正常範圍 %2..%3 µT：請遠離磁性物體</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>hard iron %1 µT is large (over 1.5 times the field): the sensor may saturate</source>
        <translation>硬鐵 %1 µT 過大（超過磁場的 1.5 倍）：感測器可能飽和</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>field strength %1 µT differs from the expected %2 µT by more than 15 %</source>
        <translation>磁場強度 %1 µT 與預期的 %2 µT 相差超過 15 %</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>The data cannot give an accurate calibration: the predicted heading error of a level module is %1 deg, at most %2 deg is accepted (hard iron +-%3 µT, soft iron +-%4 %).</source>
        <translation>這些資料無法給出準確的校準：模組水平時的預測航向誤差為 %1 deg，最多只接受 %2 deg（硬鐵 +-%3 µT，軟鐵 +-%4 %）。</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>The directions are covered, but there are too few samples or they scatter too much (%1 µT RMS about the fit): collect more, turning slowly and evenly, away from iron and electronics.</source>
        <translation>方向已覆蓋，但樣本太少或離散過大（相對擬合 %1 µT RMS）：請遠離鐵器和電子設備，緩慢均勻地旋轉，擷取更多樣本。</translation>
    </message>
    <message>
        <location line="-145"/>
        <source>Only %1 usable samples; the 2-D fit needs at least %2. Turn the module a full circle.</source>
        <translation>僅有 %1 個可用樣本；二維擬合至少需要 %2 個。請將模組轉動一整圈。</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>The horizontal samples do not describe an ellipse: turn the module one full, even circle.</source>
        <translation>水平樣本無法構成橢圓：請將模組均勻轉動一整圈。</translation>
    </message>
    <message>
        <location line="+47"/>
        <location line="+17"/>
        <source>fit error %1 % is above %2 %</source>
        <translation>擬合誤差 %1 % 高於 %2 %</translation>
    </message>
    <message>
        <location line="-12"/>
        <source>soft-iron scale %1..%2 is outside %3..%4 (a magnet or iron part very close to the module)</source>
        <translation>軟鐵縮放係數 %1..%2 超出 %3..%4（有磁鐵或鐵件非常靠近模組）</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>only %1 % of the directions are covered</source>
        <translation>方向僅覆蓋 %1 %</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1 of %2 samples were disturbed and set aside</source>
        <translation>%2 個樣本中有 %1 個受干擾，已剔除</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>2-D calibration: valid for level operation only; the vertical offset is unknown</source>
        <translation>二維校準：僅適用於水平使用；垂直方向偏移未知</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>2-D calibration: valid for level operation only</source>
        <translation>二維校準：僅適用於水平使用</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Calibration failed: %1.</source>
        <translation>校準失敗：%1。</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>The data cannot give an accurate calibration: the fit&apos;s parameters are not determined by these samples.</source>
        <translation>這些資料無法給出準確的校準：這些樣本確定不了擬合參數。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Part of the sphere is missing (a gap of %1 deg). %2, then fit again.</source>
        <translation>球面缺少一部分（空缺 %1 deg）。%2，然後重新擬合。</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Usable with care: %1.</source>
        <translation>可謹慎使用：%1。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Good calibration: predicted heading error %1 deg (level module), fit error %2 %, %3 % of the directions covered.</source>
        <translation>校準良好：預測航向誤差 %1 deg（水平放置），擬合誤差 %2 %，覆蓋了 %3 % 的方向。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Good calibration: fit error %1 %, %2 % of the directions covered.</source>
        <translation>校準良好：擬合誤差 %1 %，方向覆蓋 %2 %。</translation>
    </message>
</context>
<context>
    <name>MagEnvironmentCheck</name>
    <message>
        <location filename="../core/calib/mag_environment_check.cpp" line="+57"/>
        <source>Hold the module at the calibration spot and turn it slowly to a few orientations.</source>
        <translation>將模組拿在校準地點，緩慢轉到幾個不同姿態。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The field is %1 µT (normal: %2..%3 µT) and varies by %4 µT between orientations: you can calibrate here.</source>
        <translation>磁場為 %1 µT（正常：%2..%3 µT），不同朝向之間變化 %4 µT：可以在此校準。</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The field is %1 µT, outside the normal %2..%3 µT: a strongly magnetic object is near. Move away from it, or choose another place.</source>
        <translation>磁場為 %1 µT，超出正常範圍 %2..%3 µT：附近有強磁性物體。請遠離它，或更換位置。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The field strength varies by %1 µT between orientations (more than %2 µT): there is spatial interference here. Choose another place (outdoors, away from buildings and vehicles), or use 6-axis mode.</source>
        <translation>不同朝向之間的磁場強度變化 %1 µT（超過 %2 µT）：此處存在空間磁場干擾。請更換位置（室外，遠離建築物和車輛），或改用 6 軸模式。</translation>
    </message>
</context>
<context>
    <name>MagEnvironmentJudge</name>
    <message>
        <location filename="../core/calib/mag_environment_judge.cpp" line="+166"/>
        <source>|B| changed by %1 µT while the module was still: something near it moves or switches (a magnet, a motor, a current). Remove it or choose another place.</source>
        <translation>模組靜止時 |B| 變化了 %1 µT：附近有東西在移動或通斷（磁鐵、電機、電流）。請移走它或換一個地方。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Turn the module slowly to many orientations at the calibration spot: the field has pointed into %1 % of the sphere so far. The raw |B| (%2 µT now) includes the module&apos;s own iron, which the calibration removes, so it is not judged by itself.</source>
        <translation>請在校準位置把模組緩慢轉到多個朝向：目前磁場已指向球面的 %1 %。原始 |B|（現在 %2 µT）包含模組自身的鐵磁干擾，校準會將其去除，因此不單獨據此判斷。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>So far the field here is about %1 µT once the module&apos;s own iron (%2 µT) is taken out. Keep turning (%3 % of the sphere) for the full check.</source>
        <translation>去除模組自身的鐵磁干擾（%2 µT）後，此處磁場目前約為 %1 µT。請繼續轉動（已覆蓋球面的 %3 %）以完成完整檢查。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The field here is %1 µT once the module&apos;s own iron (%2 µT) is taken out: within the Earth&apos;s %3..%4 µT, and the same in every orientation within %5 µT. You can calibrate here.</source>
        <translation>去除模組自身的鐵磁干擾（%2 µT）後，此處磁場為 %1 µT：在地磁場的 %3..%4 µT 範圍內，且各朝向之間相差不超過 %5 µT。可以在此校準。</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The field here is %1 µT once the module&apos;s own iron (%2 µT) is taken out, outside the Earth&apos;s %3..%4 µT: a magnetic object or a steel structure is near. Move away from it, or choose another place.</source>
        <translation>去除模組自身的鐵磁干擾（%2 µT）後，此處磁場為 %1 µT，超出地磁場的 %3..%4 µT：附近有磁性物體或鋼結構。請遠離它，或換一個地方。</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Once the module&apos;s own iron is taken out, the field still differs by %1 µT between orientations (more than %2 µT): it is not uniform here. Choose another place (outdoors, away from buildings and vehicles), or use 6-axis mode.</source>
        <translation>去除模組自身的鐵磁干擾後，各朝向之間的磁場仍相差 %1 µT（超過 %2 µT）：此處磁場不均勻。請換一個地方（室外，遠離建築物和車輛），或使用 6 軸模式。</translation>
    </message>
</context>
<context>
    <name>MagnetometerFile</name>
    <message>
        <location filename="../core/record/magnetometer_file.cpp" line="+59"/>
        <source>%1 holds no magnetometer samples in µT (a %2): record the module&apos;s output with its magnetometer (HI91, HI81 or HI83)</source>
        <translation>%1 中沒有以 µT 為單位的磁力計樣本（%2）：請錄製包含磁力計的模組輸出（HI91、HI81 或 HI83）</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>line %1 is not a JSON object: %2</source>
        <translation>第 %1 行不是 JSON 物件：%2</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>line %1, key mag: three numbers [x, y, z] in µT are needed</source>
        <translation>第 %1 行，鍵 mag：需要三個以 µT 為單位的數 [x, y, z]</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>more than %1 samples</source>
        <translation>超過 %1 個樣本</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+28"/>
        <source>the file holds %1 devices (%2): choose one with --device NAME</source>
        <translation>檔案包含 %1 個裝置（%2）：請用 --device NAME 選擇一個</translation>
    </message>
    <message>
        <location line="-24"/>
        <location line="+30"/>
        <source>the file has no device %1; its devices: %2</source>
        <translation>檔案中沒有裝置 %1；其裝置：%2</translation>
    </message>
    <message>
        <location line="-28"/>
        <source>no line has a key mag (the magnetometer, µT)</source>
        <translation>沒有任何一行包含鍵 mag（磁力計，µT）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 lines without a magnetometer passed over</source>
        <translation>已略過 %1 行無磁力計資料的行</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>--device %1: the file has no device column</source>
        <translation>--device %1：檔案中沒有 device 欄</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 rows without a magnetometer passed over</source>
        <translation>已略過 %1 列無磁力計資料的列</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>cannot read %1: %2</source>
        <translation>無法讀取 %1：%2</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1 is larger than %2 MB; split it</source>
        <translation>%1 大於 %2 MB；請將其分割</translation>
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
        <translation>無法寫入 %1：%2</translation>
    </message>
</context>
<context>
    <name>McapRepair</name>
    <message>
        <location filename="../core/format/mcap/mcap_repair.cpp" line="+181"/>
        <source>%1 cannot be read: %2</source>
        <translation>無法讀取 %1：%2</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 is not an MCAP file (it does not start with MCAP&apos;s magic bytes).</source>
        <translation>%1 不是 MCAP 檔案（開頭不是 MCAP 的識別位元組）。</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>This is not an MCAP file (it does not start with MCAP&apos;s magic bytes).</source>
        <translation>這不是 MCAP 檔案（開頭不是 MCAP 的識別位元組）。</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>Cannot write %1: %2</source>
        <translation>無法寫入 %1：%2</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The file cannot be read from its start again.</source>
        <translation>無法從頭重新讀取該檔案。</translation>
    </message>
    <message>
        <location line="+25"/>
        <location line="+10"/>
        <source>Writing %1 failed: %2</source>
        <translation>寫入 %1 失敗：%2</translation>
    </message>
</context>
<context>
    <name>ModbusSimulator</name>
    <message>
        <location filename="../core/sim/modbus_simulator.cpp" line="+45"/>
        <source>The simulated Modbus device could not open %1: %2</source>
        <translation>模擬 Modbus 裝置無法開啟 %1：%2</translation>
    </message>
</context>
<context>
    <name>ModbusUi</name>
    <message>
        <location filename="../ui/families/modbus_ui.cpp" line="+19"/>
        <source>Simulated HEC495 (Modbus)</source>
        <translation>模擬 HEC495（Modbus）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Simulated HI14 (Modbus)</source>
        <translation>模擬 HI14（Modbus）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1, Modbus node %2</source>
        <translation>%1，Modbus 節點 %2</translation>
    </message>
</context>
<context>
    <name>MotionCheck</name>
    <message>
        <location filename="../core/calib/motion_check.cpp" line="+87"/>
        <source>the module moved: Allan deviation needs a still recording</source>
        <translation>模組移動過：阿倫方差需要靜止狀態下的記錄</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>gyro std dev %1 °/s, a module at rest stays below %2 °/s</source>
        <translation>陀螺儀標準差 %1 °/s，靜止的模組低於 %2 °/s</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>its rate changed by %1 °/s between 1-s windows: it was turned</source>
        <translation>其角速度在 1 秒視窗之間變化了 %1 °/s：模組被轉動過</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>it turned steadily at %1 °/s; a gyro&apos;s bias stays below %2 °/s</source>
        <translation>模組以 %1 °/s 等速轉動；陀螺儀零偏低於 %2 °/s</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>its acceleration changed by %1 G between 1-s windows: it was tilted or pushed</source>
        <translation>其加速度在 1 秒視窗之間變化了 %1 G：模組被傾斜或推動過</translation>
    </message>
</context>
<context>
    <name>MountingChoice</name>
    <message>
        <location filename="../core/settings/mounting_choice.cpp" line="+69"/>
        <source>IMU X and IMU Y cannot both point %1 / %2: they must be at right angles</source>
        <translation>IMU X 軸%1、IMU Y 軸%2 無效：兩軸必須互相垂直</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>IMU X %1, IMU Y %2, IMU Z %3 is left-handed or not at right angles: with X %1 and Y %2, Z points %4</source>
        <translation>IMU X 軸%1、IMU Y 軸%2、IMU Z 軸%3 為左手系或軸不互相垂直：X 軸%1、Y 軸%2 時，Z 軸應%4</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>no URFR code for this mounting</source>
        <translation>此安裝方式沒有對應的 URFR 代碼</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>right</source>
        <translation>向右</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>left</source>
        <translation>向左</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>forward</source>
        <translation>向前</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>back</source>
        <translation>向後</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>up</source>
        <translation>向上</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>down</source>
        <translation>向下</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>IMU X %1, IMU Y %2, IMU Z %3</source>
        <translation>IMU X 軸%1、IMU Y 軸%2、IMU Z 軸%3</translation>
    </message>
</context>
<context>
    <name>PtyBridge</name>
    <message>
        <location filename="../core/sim/pty_bridge.cpp" line="+29"/>
        <source>Cannot open a pseudo-terminal: %1</source>
        <translation>無法開啟虛擬終端機：%1</translation>
    </message>
    <message>
        <location line="+65"/>
        <source>Cannot create a pipe: %1</source>
        <translation>無法建立管道：%1</translation>
    </message>
</context>
<context>
    <name>PtySimulator</name>
    <message>
        <location filename="../core/sim/pty_simulator.cpp" line="+328"/>
        <source>Cannot open a pseudo-terminal: %1</source>
        <translation>無法開啟虛擬終端機：%1</translation>
    </message>
</context>
<context>
    <name>QtCanFrameLink</name>
    <message>
        <location filename="../core/firmware/qt_can_frame_link.cpp" line="+31"/>
        <source>the CAN plugin &quot;%1&quot; is not installed (available: %2)</source>
        <translation>未安裝 CAN 外掛程式「%1」（可用：%2）</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>cannot create the CAN device %1:%2: %3</source>
        <translation>無法建立 CAN 裝置 %1:%2：%3</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>cannot open the CAN device %1:%2: %3. Check the interface name and that it is up</source>
        <translation>無法開啟 CAN 裝置 %1:%2：%3。請檢查介面名稱以及介面是否已啟用</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>the CAN device %1:%2 did not connect within %3 ms: %4</source>
        <translation>CAN 裝置 %1:%2 在 %3 ms 內未連線：%4</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>the CAN device %1:%2 is not connected (%3); check the cable and the adapter</source>
        <translation>CAN 裝置 %1:%2 未連線（%3）；請檢查線纜和轉接器</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>closed</source>
        <translation>已關閉</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>sending a CAN frame failed: %1</source>
        <translation>傳送 CAN 幀失敗：%1</translation>
    </message>
</context>
<context>
    <name>RegisterMap</name>
    <message>
        <location filename="../core/protocol/modbus/register_map.cpp" line="+19"/>
        <source>Control: 0 saves the configuration to flash, 1 restores factory settings, 0xFF resets</source>
        <translation>控制：0 將配置儲存到快閃記憶體，1 恢復出廠設定，0xFF 重設</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Baud rate code: 0=4800 1=9600 2=19200 3=38400 4=57600 5=115200 6=230400 7=460800 8=921600</source>
        <translation>波特率代碼：0=4800 1=9600 2=19200 3=38400 4=57600 5=115200 6=230400 7=460800 8=921600</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Modbus node ID, 1-128; takes effect at once</source>
        <translation>Modbus 節點 ID，1-128；立即生效</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>0: 6-axis (relative heading, 0 at power-up), 1: 9-axis (magnetic, absolute heading)</source>
        <translation>0：6 軸（相對航向角，上電時為 0），1：9 軸（地磁，絕對航向角）</translation>
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
        <translation>磁場 X</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Magnetic field Y</source>
        <translation>磁場 Y</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Magnetic field Z</source>
        <translation>磁場 Z</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Roll (R_H high word, R_L low word)</source>
        <translation>橫滾角（R_H 高位字，R_L 低位字）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Pitch (P_H high word, P_L low word)</source>
        <translation>俯仰角（P_H 高位字，P_L 低位字）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Yaw (Y_H high word, Y_L low word)</source>
        <translation>航向角（Y_H 高位字，Y_L 低位字）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Temperature</source>
        <translation>溫度</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Pressure (PRS_H high word, PRS_L low word)</source>
        <translation>氣壓（PRS_H 高位字，PRS_L 低位字）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Quaternion W</source>
        <translation>四元數 W</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Quaternion X</source>
        <translation>四元數 X</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Quaternion Y</source>
        <translation>四元數 Y</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Quaternion Z</source>
        <translation>四元數 Z</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Inclinometer X angle (dual axis: +-180; single axis: 0-360)</source>
        <translation>傾角儀 X 軸角度（雙軸：+-180；單軸：0-360）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Inclinometer Y angle (dual axis: +-90; single axis: reserved)</source>
        <translation>傾角儀 Y 軸角度（雙軸：+-90；單軸：保留）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ship heave displacement</source>
        <translation>船舶垂蕩位移</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ship heave period</source>
        <translation>船舶垂蕩週期</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Device name (ASCII, 8 registers)</source>
        <translation>裝置名稱（ASCII，8 個暫存器）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Software version (152 = V1.52)</source>
        <translation>軟體版本（152 = V1.52）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Bootloader version (107 = V1.07)</source>
        <translation>開機載入程式版本（107 = V1.07）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Unique serial number (4 registers)</source>
        <translation>唯一序號（4 個暫存器）</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+2"/>
        <source>Auto-level: 3 levels once when pitch and roll are within 15 deg of 0/0 or 0/180, 5 cancels (the register table, which calls other values invalid). The manual&apos;s worked example writes 2 to level; ImuDesk accepts 2 and 3, and its own level action sends 2, byte for byte as the example</source>
        <translation>自動調平：3 在俯仰角與橫滾角與 0/0 或 0/180 相差 15 deg 以內時執行一次調平，5 取消（暫存器表，其中其他值皆為無效）。手冊範例寫入 2 進行調平；ImuDesk 接受 2 與 3，其自身的調平操作傳送 2，與範例逐位元組一致</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Mounting: the URFR code (0x18 = 024 horizontal, 0x2B = 043, 0x34 = 052, 0x208 = 520, 0x1A5 = 421)</source>
        <translation>安裝方式：URFR 代碼（0x18 = 024 水平，0x2B = 043，0x34 = 052，0x208 = 520，0x1A5 = 421）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Mounting: 0 horizontal, 1 Y axis down, 2 Y axis up, 3 X axis up, 4 X axis down</source>
        <translation>安裝方式：0 水平，1 Y 軸朝下，2 Y 軸朝上，3 X 軸朝上，4 X 軸朝下</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>Pitch (X axis) angle, float</source>
        <translation>俯仰角（X 軸），浮點數</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Roll (Y axis) angle, float</source>
        <translation>橫滾角（Y 軸），浮點數</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Heading (Z axis) angle, float</source>
        <translation>航向角（Z 軸），浮點數</translation>
    </message>
</context>
<context>
    <name>ReplayUi</name>
    <message>
        <location filename="../ui/families/replay_ui.cpp" line="+18"/>
        <source>Replay of %1</source>
        <translation>重播 %1</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Replay</source>
        <translation>重播</translation>
    </message>
</context>
<context>
    <name>Reply</name>
    <message>
        <location filename="../core/protocol/witlink/reply.cpp" line="+149"/>
        <source>no error</source>
        <translation>無錯誤</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a reply command that the HEC495 manual does not list</source>
        <translation>HEC495 手冊中未列出的回應指令</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a data field of the wrong length for this reply</source>
        <translation>此回應的資料欄位長度錯誤</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a BCD value with a digit above 9 or a bad sign nibble</source>
        <translation>BCD 值中有大於 9 的數字或錯誤的符號半位元組</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a status byte that is neither 00 (success) nor FF (failure)</source>
        <translation>狀態位元組既不是 00（成功）也不是 FF（失敗）</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1: invalid reply (%2)</source>
        <translation>%1：無效回應（%2）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: %2 deg</source>
        <translation>%1：%2 deg</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>pitch %1 deg, roll %2 deg, heading %3 deg</source>
        <translation>俯仰角 %1 deg，橫滾角 %2 deg，航向角 %3 deg</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>pitch %1 deg, roll %2 deg, heading %3 deg, time %4 ms</source>
        <translation>俯仰角 %1 deg，橫滾角 %2 deg，航向角 %3 deg，時間 %4 ms</translation>
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
        <translation>%1：裝置回報失敗</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>calibration saved: fit error %1, %2 points</source>
        <translation>校準已儲存：擬合誤差 %1，%2 個點</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>calibration point collected: %1 points</source>
        <translation>已採集校準點：%1 個點</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>address %1</source>
        <translation>位址 %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>unknown reply</source>
        <translation>未知回應</translation>
    </message>
</context>
<context>
    <name>SDO</name>
    <message>
        <location filename="../core/protocol/can/sdo.cpp" line="+11"/>
        <source>toggle bit not alternated</source>
        <translation>切換位元未交替</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>SDO protocol timed out</source>
        <translation>SDO 協定逾時</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>command specifier not valid or unknown</source>
        <translation>指令識別碼無效或未知</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>out of memory</source>
        <translation>記憶體不足</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unsupported access to an object</source>
        <translation>不支援對物件的此種存取</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>attempt to read a write-only object</source>
        <translation>嘗試讀取唯寫物件</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>attempt to write a read-only object</source>
        <translation>嘗試寫入唯讀物件</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>object does not exist in the object dictionary</source>
        <translation>物件字典中不存在該物件</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>data type does not match, length of service parameter does not match</source>
        <translation>資料類型不符，服務參數長度不符</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>sub-index does not exist</source>
        <translation>子索引不存在</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>invalid value for parameter</source>
        <translation>參數值無效</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>value of parameter written too high</source>
        <translation>寫入的參數值過高</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>value of parameter written too low</source>
        <translation>寫入的參數值過低</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>general error</source>
        <translation>一般錯誤</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>data cannot be transferred or stored to the application</source>
        <translation>資料無法傳送或儲存到應用程式</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>data cannot be transferred because of the present device state</source>
        <translation>因裝置目前狀態，資料無法傳送</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>abort code 0x%1</source>
        <translation>中止代碼 0x%1</translation>
    </message>
    <message>
        <location line="+122"/>
        <source>SDO write %1 = %2 (%3 bytes)</source>
        <translation>SDO 寫入 %1 = %2（%3 位元組）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>SDO segmented write %1, %2 bytes</source>
        <translation>SDO 分段寫入 %1，%2 位元組</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>SDO segment</source>
        <translation>SDO 分段</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>SDO write %1 confirmed</source>
        <translation>SDO 寫入 %1 已確認</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>SDO segment confirmed</source>
        <translation>SDO 分段已確認</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>SDO read %1</source>
        <translation>SDO 讀取 %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>SDO read %1 -&gt; %2</source>
        <translation>SDO 讀取 %1 -&gt; %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>SDO read %1: segmented, %2 bytes</source>
        <translation>SDO 讀取 %1：分段，%2 位元組</translation>
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
        <translation>裝置中止了傳輸：%1</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>the device confirmed a segment with the wrong toggle bit</source>
        <translation>裝置確認分段時切換位元錯誤</translation>
    </message>
</context>
<context>
    <name>SampleAnalyzer</name>
    <message>
        <location filename="../core/record/sample_analyzer.cpp" line="+157"/>
        <source>cannot judge: the recording is too short</source>
        <translation>無法判斷：記錄太短</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>%1 frames over %2 s; the random walk is read at τ = %3 s, which needs at least %4 s of a still module (%5 s for 10 % uncertainty)</source>
        <translation>%2 s 內共 %1 幀；隨機遊走取自 τ = %3 s，至少需要模組靜止 %4 s 的資料（不確定度 10 % 需要 %5 s）</translation>
    </message>
</context>
<context>
    <name>SampleCsv</name>
    <message>
        <location filename="../core/calib/sample_csv.cpp" line="+26"/>
        <source>line %1 is longer than %2 characters</source>
        <translation>第 %1 行超過 %2 個字元</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>line %1 has more than %2 columns</source>
        <translation>第 %1 行超過 %2 欄</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>line %1: the header has an empty column name</source>
        <translation>第 %1 行：標題列有空白的欄位名稱</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+86"/>
        <source>line %1: a header row of column names is required (e.g. mag_x,mag_y,mag_z)</source>
        <translation>第 %1 行：必須有欄位名稱標題列（例如 mag_x,mag_y,mag_z）</translation>
    </message>
    <message>
        <location line="-78"/>
        <location line="+89"/>
        <source>line %1 has %2 values, the header has %3 columns</source>
        <translation>第 %1 行有 %2 個值，標題列有 %3 欄</translation>
    </message>
    <message>
        <location line="-84"/>
        <location line="+105"/>
        <source>more than %1 rows</source>
        <translation>超過 %1 列</translation>
    </message>
    <message>
        <location line="-98"/>
        <location line="+106"/>
        <source>line %1, column %2: &apos;%3&apos; is not a number</source>
        <translation>第 %1 行第 %2 欄：「%3」不是數字</translation>
    </message>
    <message>
        <location line="-94"/>
        <location line="+106"/>
        <source>the file is empty: a header row and samples are needed</source>
        <translation>檔案為空：需要標題列和樣本</translation>
    </message>
    <message>
        <location line="-60"/>
        <source>line %1: the column %2 is missing (needed: %3); the header has: %4</source>
        <translation>第 %1 行：缺少欄 %2（需要：%3）；表頭為：%4</translation>
    </message>
    <message>
        <location line="+92"/>
        <source>the columns mag_x, mag_y and mag_z (µT) are needed; the header has: %1</source>
        <translation>需要 mag_x、mag_y 和 mag_z 列（單位 µT）；表頭中只有：%1</translation>
    </message>
</context>
<context>
    <name>SampleFile</name>
    <message>
        <location filename="../core/record/sample_file.cpp" line="+53"/>
        <source>--device chooses a device of a session: %1 is not one</source>
        <translation>--device 用於選擇工作階段中的裝置：%1 不是工作階段</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1 is a folder without session.json: give a file, or a recorded session&apos;s folder</source>
        <translation>%1 是不含 session.json 的資料夾：請給出一個檔案，或已錄製工作階段的資料夾</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>the session %1 has no device %2; its devices: %3</source>
        <translation>工作階段 %1 中沒有裝置 %2；其裝置：%3</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the session %1 holds %2 devices (%3): choose one with --device NAME</source>
        <translation>工作階段 %1 包含 %2 個裝置（%3）：請用 --device NAME 選擇一個</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>session</source>
        <translation>工作階段</translation>
    </message>
</context>
<context>
    <name>SerialByteLink</name>
    <message>
        <location filename="../core/firmware/serial_byte_link.cpp" line="+62"/>
        <location line="+24"/>
        <source>the port %1 is not open</source>
        <translation>串列埠 %1 未開啟</translation>
    </message>
    <message>
        <location line="-18"/>
        <source>writing to %1 failed: %2</source>
        <translation>寫入 %1 失敗：%2</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>writing to %1 stalled: %2</source>
        <translation>寫入 %1 停滯：%2</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>reading from %1 failed: %2 (was the device unplugged?)</source>
        <translation>從 %1 讀取失敗：%2（裝置是否已拔除？）</translation>
    </message>
</context>
<context>
    <name>SessionExporter</name>
    <message>
        <location filename="../core/record/session_exporter.cpp" line="+184"/>
        <source>A session of several devices exports to tidy CSV, JSON Lines, MCAP or MATLAB; the vendor&apos;s layout has one device per file (export each capture on its own for it).</source>
        <translation>多裝置工作階段可匯出為整齊 CSV、JSON Lines、MCAP 或 MATLAB；廠商格式每個檔案只含一台裝置（如需該格式，請逐一匯出各記錄）。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>A grid or trigger pairs are written as tidy CSV (--format csv).</source>
        <translation>網格或觸發配對以整齊 CSV 寫出（--format csv）。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>No output file was given.</source>
        <translation>未指定輸出檔案。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>A grid of at least 0.01 ms, or a pulse rate up to 10 kHz, not both.</source>
        <translation>網格至少 0.01 ms，或脈衝頻率不超過 10 kHz，二者不可同時指定。</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Device %1: %2</source>
        <translation>裝置 %1：%2</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Device %1 dropped out during the recording (session.json says when); its data ends there.</source>
        <translation>裝置 %1 在錄製期間斷線（時間見 session.json）；其資料到此為止。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The session holds no device.</source>
        <translation>此工作階段中沒有裝置。</translation>
    </message>
    <message>
        <location line="-128"/>
        <location line="+141"/>
        <source>Cannot write %1: %2</source>
        <translation>無法寫入 %1：%2</translation>
    </message>
    <message>
        <location line="-108"/>
        <location line="+40"/>
        <location line="+104"/>
        <location line="+85"/>
        <source>Export cancelled.</source>
        <translation>匯出已取消。</translation>
    </message>
    <message>
        <location line="-26"/>
        <source>%1 frames of devices whose clock never aligned have no pulse index.</source>
        <translation>時鐘從未對齊的裝置有 %1 幀沒有脈衝序號。</translation>
    </message>
    <message>
        <location line="+88"/>
        <source>Device %1 (%2): nothing in its capture that ImuDesk decodes offline (Modbus captures are not decoded yet); it is left out.</source>
        <translation>裝置 %1（%2）：其記錄中沒有 ImuDesk 可離線解碼的內容（Modbus 記錄尚不能解碼），已略去。</translation>
    </message>
    <message>
        <location line="-285"/>
        <location line="+290"/>
        <source>Writing %1 failed: %2. Free some space or choose another place.</source>
        <translation>寫入 %1 失敗：%2。請釋放一些空間或選擇其他位置。</translation>
    </message>
</context>
<context>
    <name>SettingCatalog</name>
    <message>
        <location filename="../core/settings/setting_catalog.cpp" line="+22"/>
        <source>Output of this message on this port: off, every period (ONTIME 0.001 s = 1 kHz .. 1 s = 1 Hz) or on each SYNC_IN/PPS rising edge (ONMARK 1).</source>
        <translation>此訊息在此串列埠上的輸出：關閉、按週期輸出（ONTIME 0.001 s = 1 kHz .. 1 s = 1 Hz），或在每個 SYNC_IN/PPS 上升沿輸出（ONMARK 1）。</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Serial baud rate</source>
        <translation>串列埠波特率</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>SERIALCONFIG: the UART switches at once; ImuDesk follows and confirms with LOG VERSION. v1.7.1: 4800 .. 921600; v1.6.6: 9600, 115200, 256000, 460800, 921600.</source>
        <translation>SERIALCONFIG：UART 立即切換；ImuDesk 隨之切換並以 LOG VERSION 確認。v1.7.1：4800 .. 921600；v1.6.6：9600、115200、256000、460800、921600。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Data output</source>
        <translation>資料輸出</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>LOG ENABLE / LOG DISABLE: all data frames on or off. Output is enabled again after every start.</source>
        <translation>LOG ENABLE / LOG DISABLE：開啟或關閉所有資料幀。每次啟動後輸出都會重新啟用。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>HI91 output (float IMU frame)</source>
        <translation>HI91 輸出（浮點 IMU 幀）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>HI92 output (integer IMU frame)</source>
        <translation>HI92 輸出（整數 IMU 幀）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>HI81 output (INS frame)</source>
        <translation>HI81 輸出（組合導航幀）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>HI83 output (variable frame)</source>
        <translation>HI83 輸出（可變幀）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>NMEA GGA output</source>
        <translation>NMEA GGA 輸出</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>NMEA RMC output</source>
        <translation>NMEA RMC 輸出</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>NMEA SXT output</source>
        <translation>NMEA SXT 輸出</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>HI83 fields (data_bitmap)</source>
        <translation>HI83 欄位（data_bitmap）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>LOG HI83 MAP: one bit per data segment (bit 0 acc, 1 gyr, 2 mag, 3 Euler, 4 quaternion, 5 time us, 6 UTC, 7 pressure, ..., 25 filter update counters, 26 and 27 filter biases, 28 GNSS accuracy, 29 dual-antenna heading, 30 and 31 GNSS position and velocity; 20 to 24 are reserved); default 0x000000FF.</source>
        <translation>LOG HI83 MAP：每位對應一個資料段（位 0 加速度、1 角速度、2 磁場、3 尤拉角、4 四元數、5 時間 us、6 UTC、7 氣壓、……、25 濾波器量測更新計數、26 和 27 濾波器零偏、28 GNSS 精度、29 雙天線航向、30 和 31 GNSS 位置與速度；20 至 24 保留）；預設 0x000000FF。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Working mode</source>
        <translation>工作模式</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CONFIG ATT MODE: 0 VRU (6-axis), 1 AHRS (9-axis, magnetometer aided; calibrate the magnetometer first, avoid near motors and indoors), 4 humanoid robot (v1.7.1).</source>
        <translation>CONFIG ATT MODE：0 VRU（6 軸），1 AHRS（9 軸，磁力計輔助；請先進行地磁校準，避免靠近馬達及在室內使用），4 人形機器人（v1.7.1）。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Mounting (URFR)</source>
        <translation>安裝方式（URFR）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CONFIG IMU URFR: which sensor direction each user axis is (code ABC, 24 right-handed codes; 24 = X right, Y forward, Z up). Firmware below 1.7.1 takes the nine numbers of the matrix C as the manual&apos;s named mountings print it (X_U = C * X_B; 1,0,0,0,0,1,0,-1,0 is Y down).</source>
        <translation>CONFIG IMU URFR：每個使用者座標軸對應的感測器方向（代碼 ABC，共 24 個右手系代碼；24 = X 向右，Y 向前，Z 向上）。1.7.1 以下的韌體接受矩陣 C 的九個數，與手冊各具名安裝方式的範例一致（X_U = C * X_B；1,0,0,0,0,1,0,-1,0 為 Y 軸朝下）。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>World frame</source>
        <translation>世界座標系</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CONFIG IMU COORD: 0 East-North-Up (ENU, default), 4 North-West-Up (NWU).</source>
        <translation>CONFIG IMU COORD：0 東-北-天（ENU，預設），4 北-西-天（NWU）。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>PMUX1 pin (SYNC_IN/PPS input)</source>
        <translation>PMUX1 腳位（SYNC_IN/PPS 輸入）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PMUX2 pin (SOUT sync output)</source>
        <translation>PMUX2 腳位（SOUT 同步輸出）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PMUX3 pin (status LED)</source>
        <translation>PMUX3 腳位（狀態 LED）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>CONFIG PMUXn IOm: the IO pin that carries this function (defaults PMUX1 IO1, PMUX2 IO2, PMUX3 IO5). Not every IO is brought out on every product.</source>
        <translation>CONFIG PMUXn IOm：承載此功能的 IO 腳位（預設 PMUX1 IO1，PMUX2 IO2，PMUX3 IO5）。並非每款產品都引出所有 IO。</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>SOUT divider</source>
        <translation>SOUT 分頻</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CONFIG PMUX2 DIV: one SOUT pulse every N frames (1 .. 1000, default 1): at 100 Hz output, 5 gives 20 Hz pulses for a camera.</source>
        <translation>CONFIG PMUX2 DIV：每 N 幀輸出一個 SOUT 脈衝（1 .. 1000，預設 1）：輸出為 100 Hz 時，設為 5 即可為相機提供 20 Hz 脈衝。</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Background magnetometer calibration</source>
        <translation>背景地磁校準</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CONFIG IMU_EN_MCAL (v1.6.6): 1 calibrates the magnetometer in the background (factory default), 0 stops it; SAVECONFIG keeps it.</source>
        <translation>CONFIG IMU_EN_MCAL（v1.6.6）：1 在背景執行地磁校準（出廠預設），0 停止；SAVECONFIG 可保留此設定。</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Heading reset</source>
        <translation>航向角歸零</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Sets the current heading to 0. Keep the device still while it runs.</source>
        <translation>將目前航向角設為 0。執行期間請保持裝置靜止。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Relative level (zero pitch and roll)</source>
        <translation>相對調平（俯仰角與橫滾角歸零）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Makes the current pitch and roll the zero, whatever the tilt (no check). Keep the device still; ATT RST 5 undoes it; SAVECONFIG keeps it.</source>
        <translation>將目前的俯仰角與橫滾角設為零點，不論傾斜多少（不做檢查）。請保持裝置靜止；ATT RST 5 可撤銷；SAVECONFIG 可保留此設定。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Automatic levelling</source>
        <translation>自動調平</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Only when nearly level: pitch and roll both below 5 deg levels to 0/0, pitch below 5 deg and roll near 180 deg levels to 0/180; otherwise refused (ERR). Keep the device still. Permanent: ATT RST 5 does not undo it, only a factory reset does.</source>
        <translation>僅在接近水平時有效：俯仰角與橫滾角均小於 5 deg 時調平到 0/0，俯仰角小於 5 deg 且橫滾角接近 180 deg 時調平到 0/180；否則拒絕（ERR）。請保持裝置靜止。永久生效：ATT RST 5 無法撤銷，只有恢復出廠設定才能清除。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Cancel relative level</source>
        <translation>取消相對調平</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Clears the relative pitch/roll zero of ATT RST 2 and returns to absolute angles.</source>
        <translation>清除 ATT RST 2 設定的俯仰/橫滾相對零點，恢復為絕對角度。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Set heading (v1.6.6)</source>
        <translation>設定航向角（v1.6.6）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CONFIG YAW MODE DEG: MODE 1 sets the heading to DEG (absolute), MODE 0 adds DEG (relative); -180 .. 180 deg; at once, not saved. Value &quot;MODE,DEG&quot;, e.g. 1,16.</source>
        <translation>CONFIG YAW MODE DEG：MODE 1 將航向角設為 DEG（絕對），MODE 0 在目前值上加 DEG（相對）；-180 .. 180 deg；立即生效，不儲存。值格式為 &quot;MODE,DEG&quot;，例如 1,16。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Save to flash</source>
        <translation>儲存到快閃記憶體</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Saves every setting to flash so that it survives a reset.</source>
        <translation>將所有設定儲存到快閃記憶體，重設後仍保留。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Reboot</source>
        <translation>重新啟動</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Resets the module (same as a power cycle): unsaved settings are lost, saved CONFIG settings take effect.</source>
        <translation>重設模組（等同斷電重啟）：未儲存的設定會遺失，已儲存的 CONFIG 設定生效。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Factory reset</source>
        <translation>恢復出廠設定</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Restores the factory settings, saves them and resets: baud 115200, HI91 at 100 Hz, mounting 24, working mode, PMUX pins, output messages and ATT RST 3 levelling are all lost.</source>
        <translation>恢復出廠設定、儲存並重設：波特率 115200、HI91 100 Hz、安裝方式 24；工作模式、PMUX 腳位、輸出訊息及 ATT RST 3 調平均會遺失。</translation>
    </message>
    <message>
        <location line="+69"/>
        <source>VRU (6-axis)</source>
        <translation>VRU（6 軸）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>AHRS (9-axis, magnetometer aided)</source>
        <translation>AHRS（9 軸，磁力計輔助）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Humanoid robot</source>
        <translation>人形機器人</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>East-North-Up (ENU)</source>
        <translation>東-北-天（ENU）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>North-West-Up (NWU)</source>
        <translation>北-西-天（NWU）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Off</source>
        <translation>關閉</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>On (factory default)</source>
        <translation>開啟（出廠預設）</translation>
    </message>
    <message>
        <location line="+65"/>
        <location line="+10"/>
        <source>not in the manual for firmware %1</source>
        <translation>韌體 %1 的手冊中沒有此項</translation>
    </message>
    <message>
        <location line="-8"/>
        <location line="+10"/>
        <source>%1 has no %2 (v1.7.1 feature table)</source>
        <translation>%1 沒有 %2（v1.7.1 功能表）</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1=%2: %3</source>
        <translation>%1=%2：%3</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>a baud rate is a whole number</source>
        <translation>波特率必須是整數</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>firmware below 1.7.1 takes 9600, 115200, 256000, 460800 or 921600</source>
        <translation>1.7.1 以下的韌體支援 9600、115200、256000、460800 或 921600</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>supported rates are 4800, 9600, 19200, 38400, 57600, 115200, 230400, 256000, 460800 and 921600</source>
        <translation>支援的波特率為 4800、9600、19200、38400、57600、115200、230400、256000、460800 和 921600</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>use ENABLE or DISABLE</source>
        <translation>請使用 ENABLE 或 DISABLE</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>use a period in seconds (0.001 .. 1, 0 = off), ONMARK or OFF</source>
        <translation>請使用以秒為單位的週期（0.001 .. 1，0 = 關閉）、ONMARK 或 OFF</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>use a bitmap such as 0x000000FF</source>
        <translation>請使用位元圖，例如 0x000000FF</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>not one of the documented values</source>
        <translation>不是文件中列出的值</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 (%2) is not available on this model or firmware</source>
        <translation>%1（%2）在此型號或韌體上不可用</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>not one of the 24 right-handed URFR codes</source>
        <translation>不是 24 個右手系 URFR 代碼之一</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the matrix is nine numbers C00,C01,...,C22</source>
        <translation>矩陣為九個數 C00,C01,...,C22</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>firmware 1.7.1 takes only the 24 URFR codes</source>
        <translation>韌體 1.7.1 只接受 24 個 URFR 代碼</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>use a pin IO1 .. IO%1</source>
        <translation>請使用腳位 IO1 .. IO%1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>use a whole number %1 .. %2</source>
        <translation>請使用 %1 .. %2 之間的整數</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>unknown setting kind</source>
        <translation>未知的設定類型</translation>
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
        <translation>%1 不需要值</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>YAW needs MODE,DEG (MODE 0 relative or 1 absolute, DEG -180 .. 180), e.g. YAW=1,16</source>
        <translation>YAW 需要 MODE,DEG（MODE 0 相對或 1 絕對，DEG -180 .. 180），例如 YAW=1,16</translation>
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
        <translation>關閉</translation>
    </message>
    <message>
        <location line="-31"/>
        <source>on SYNC_IN pulse (ONMARK 1)</source>
        <translation>在 SYNC_IN 脈衝時輸出（ONMARK 1）</translation>
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
        <translation>矩陣 %1</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>enabled</source>
        <translation>已啟用</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>disabled</source>
        <translation>已停用</translation>
    </message>
    <message>
        <location line="+45"/>
        <source>after SAVECONFIG and a reset</source>
        <translation>SAVECONFIG 並重設後生效</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>at once; SAVECONFIG keeps it after a reset</source>
        <translation>立即生效；SAVECONFIG 可在重設後保留</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>at once; not saved (enabled again after every start)</source>
        <translation>立即生效；不儲存（每次啟動後重新啟用）</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>LOG COMCONFIG: %1</source>
        <translation>LOG COMCONFIG：%1</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>magnetometer aiding</source>
        <translation>磁力計輔助</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>user attitude calibration</source>
        <translation>使用者姿態校準</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>IO pin mapping (PMUX)</source>
        <translation>IO 腳位映射（PMUX）</translation>
    </message>
</context>
<context>
    <name>SimulatedCanFrameLink</name>
    <message>
        <location filename="../core/sim/simulated_can_frame_link.cpp" line="+18"/>
        <source>the simulated CAN bus is not connected</source>
        <translation>模擬 CAN 匯流排未連線</translation>
    </message>
</context>
<context>
    <name>SphereCoverage</name>
    <message>
        <location filename="../core/calib/sphere_coverage.cpp" line="+139"/>
        <source>Turn the module slowly about each of its axes: no direction is covered yet</source>
        <translation>請繞模組各軸緩慢轉動：尚未覆蓋任何方向</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Turn the module so that its %1%2 axis points along the magnetic field (towards north and, in the northern hemisphere, down)</source>
        <translation>轉動模組，使其 %1%2 軸沿磁場方向（指向北方，在北半球還要朝下）</translation>
    </message>
</context>
<context>
    <name>StreamDecoder</name>
    <message>
        <location filename="../core/decode/stream_decoder.cpp" line="+56"/>
        <source>The capture is of a %1 link: its registers were polled, and ImuDesk does not decode Modbus captures offline yet.</source>
        <translation>此擷取檔來自 %1 鏈路：其暫存器是輪詢讀取的，ImuDesk 尚不支援離線解碼 Modbus 擷取檔。</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The capture is of a &quot;%1&quot; link, which this version of ImuDesk cannot decode (it decodes: %2). Open it with the version that recorded it.</source>
        <translation>此擷取檔來自「%1」鏈路，此版本的 ImuDesk 無法解碼（可解碼：%2）。請用錄製它的版本開啟。</translation>
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
        <translation>閒置</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>checking the image</source>
        <translation>正在檢查映像</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>identifying the module</source>
        <translation>正在識別模組</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>entering the bootloader</source>
        <translation>正在進入開機載入程式</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>contacting the bootloader</source>
        <translation>正在連線開機載入程式</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>reading the bootloader&apos;s properties</source>
        <translation>正在讀取開機載入程式屬性</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>erasing</source>
        <translation>正在抹除</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>writing</source>
        <translation>正在寫入</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>verifying</source>
        <translation>正在驗證</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>restarting the module</source>
        <translation>正在重新啟動模組</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>confirming the new version</source>
        <translation>正在確認新版本</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>done</source>
        <translation>完成</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>failed</source>
        <translation>失敗</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cancelled</source>
        <translation>已取消</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>the image is empty</source>
        <translation>映像為空</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the image starts at %1, which is not a multiple of 4; the bootloader writes whole words</source>
        <translation>映像起始於 %1，不是 4 的倍數；開機載入程式以整字寫入</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the image starts at %1, below the application area at %2 (that is the bootloader); this is not an application image for this module</source>
        <translation>映像起始於 %1，低於位於 %2 的應用程式區（其下方為開機載入程式）；這不是此模組的應用程式映像</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the image ends at %1, beyond the end of the flash at %2; it does not fit this module</source>
        <translation>映像結束於 %1，超出位於 %2 的快閃記憶體末端；無法放入此模組</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>the image (%1..%2) is outside the module&apos;s flash (%3..%4, %5 bytes reported by the bootloader)</source>
        <translation>映像（%1..%2）位於模組快閃記憶體（%3..%4，開機載入程式回報 %5 位元組）之外</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the image has %1 bytes, the module&apos;s flash only %2</source>
        <translation>映像有 %1 位元組，而模組快閃記憶體只有 %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the image starts at %1, which is not on a flash sector boundary (sectors of %2 bytes); the erase would destroy the bytes before it</source>
        <translation>映像起始於 %1，不在快閃記憶體磁區邊界上（磁區大小 %2 位元組）；抹除會破壞其前面的位元組</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the image starts at %1, below the application area at %2</source>
        <translation>映像起始於 %1，低於位於 %2 的應用程式區</translation>
    </message>
    <message>
        <location line="+101"/>
        <source>reading the maximum packet size failed: %1</source>
        <translation>讀取最大封包大小失敗：%1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>reading the flash size failed: %1</source>
        <translation>讀取快閃記憶體大小失敗：%1</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>the bootloader reports a maximum packet size of %1 bytes; it cannot take data</source>
        <translation>開機載入程式回報最大封包大小為 %1 位元組；無法接收資料</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the bootloader reports no flash</source>
        <translation>開機載入程式回報沒有快閃記憶體</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>bootloader: max packet %1 bytes, flash %2 bytes from %3, sectors of %4 bytes, bootloader version %5, KBOOT %6%7.%8.%9</source>
        <translation>開機載入程式：最大封包 %1 位元組，快閃記憶體 %2 位元組（起始於 %3），磁區 %4 位元組，開機載入程式版本 %5，KBOOT %6%7.%8.%9</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>refused before contacting the module: %1</source>
        <translation>連線模組前已拒絕：%1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>image: %1 bytes at %2, CRC-32 %3</source>
        <translation>映像：%1 位元組，位於 %2，CRC-32 %3</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>module %1, firmware %2, bootloader %3</source>
        <translation>模組 %1，韌體 %2，開機載入程式 %3</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the module is already in its bootloader (an earlier update was interrupted); run the update again and allow finishing it</source>
        <translation>模組已處於開機載入程式中（先前的更新被中斷）；請重新執行更新並讓其完成</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the module is already in its bootloader: an earlier update was interrupted; finishing it</source>
        <translation>模組已處於開機載入程式中：先前的更新被中斷；正在完成更新</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>nothing answered at %1 baud: neither the application (LOG VERSION) nor the bootloader (ping). Check the port, the baud rate and the power</source>
        <translation>以 %1 波特率無任何回應：應用程式（LOG VERSION）和開機載入程式（連線偵測）均未回應。請檢查串列埠、波特率和電源</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>cancelled; the module was not changed</source>
        <translation>已取消；模組未變更</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>the module did not enter its bootloader: %1</source>
        <translation>模組未進入開機載入程式：%1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>bootloader answers: protocol %1%2.%3.%4</source>
        <translation>開機載入程式回應：協定 %1%2.%3.%4</translation>
    </message>
    <message>
        <location line="+13"/>
        <location line="+16"/>
        <source>could not restart the module: %1</source>
        <translation>無法重新啟動模組：%1</translation>
    </message>
    <message>
        <location line="-15"/>
        <source>refused before erasing: %1</source>
        <translation>抹除前已拒絕：%1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>cancelled before erasing; the module was not changed</source>
        <translation>抹除前已取消；模組未變更</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>erasing %1 bytes at %2</source>
        <translation>正在抹除 %1 位元組，位於 %2</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>refused before erasing: %1; the module was not changed</source>
        <translation>抹除前已拒絕：%1；模組未變更</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>erasing failed: %1. The module stays in its bootloader; run the update again</source>
        <translation>抹除失敗：%1。模組停留在開機載入程式中；請重新執行更新</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>cancelled while writing (%1). The module stays in its bootloader without a valid application; run the update again to finish it</source>
        <translation>寫入時已取消（%1）。模組停留在開機載入程式中，沒有有效的應用程式；請重新執行更新以完成</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>writing failed: %1. The module stays in its bootloader; run the update again</source>
        <translation>寫入失敗：%1。模組停留在開機載入程式中；請重新執行更新</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 bytes written in %2 s (%3 bytes/s, %4 NAK, %5 packets resent)</source>
        <translation>%2 s 內寫入 %1 位元組（%3 位元組/s，%4 次 NAK，重傳 %5 個封包）</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>cancelled while verifying; the module stays in its bootloader; run the update again</source>
        <translation>驗證時已取消；模組停留在開機載入程式中；請重新執行更新</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the image was written but cannot be verified: the bootloader does not offer ReadMemory (%1). The module was not restarted</source>
        <translation>映像已寫入但無法驗證：開機載入程式不提供 ReadMemory（%1）。模組未重新啟動</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>verifying failed: %1. Run the update again</source>
        <translation>驗證失敗：%1。請重新執行更新</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>verification failed at %1: wrote %2, read %3. Run the update again</source>
        <translation>在 %1 處驗證失敗：寫入 %2，讀回 %3。請重新執行更新</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>verified: %1 bytes read back and compared</source>
        <translation>已驗證：已讀回並比對 %1 位元組</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the image is written and verified, but the restart failed: %1. Power-cycle the module</source>
        <translation>映像已寫入並驗證，但重新啟動失敗：%1。請將模組斷電重啟</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>the image is written and verified, but the application did not answer LOG VERSION within %1 s after the restart; the image may not be a firmware for this module</source>
        <translation>映像已寫入並驗證，但重新啟動後 %1 s 內應用程式未回應 LOG VERSION；該映像可能不是此模組的韌體</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the image is written and verified, but the application did not answer LOG VERSION at %1 baud within %2 s after the restart, nor at any other rate; the image may not be a firmware for this module</source>
        <translation>映像已寫入並校驗，但重新啟動後應用程式在 %2 秒內未在 %1 波特率下回應 LOG VERSION，在其他波特率下也沒有；該映像可能不是本模組的韌體</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>updated: firmware %1 → %2, %3 bytes verified by read-back</source>
        <translation>已更新：韌體 %1 → %2，已透過回讀驗證 %3 位元組</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>. The module restarted at %1 baud, the rate saved in it: the update ran at %2 baud, a rate that was set but not saved. It is connected again at %1 baud</source>
        <translation>。模組以其儲存的波特率 %1 重新啟動：更新是在 %2 波特率下進行的，該波特率已設定但未儲存。現已重新以 %1 波特率連線</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>no answer at %1 baud: looking for the application at %2 baud</source>
        <translation>%1 波特率下無應答：改在 %2 波特率下尋找應用程式</translation>
    </message>
</context>
<context>
    <name>VendorCsvImporter</name>
    <message>
        <location filename="../core/decode/hipnuc_vendor_csv_reader.cpp" line="+95"/>
        <source>Cannot open %1: %2</source>
        <translation>無法開啟 %1：%2</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>line %1 is longer than %2 characters</source>
        <translation>第 %1 行超過 %2 個字元</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>line %1 is not the vendor&apos;s HI91 CSV header (it starts with &quot;%2&quot;)</source>
        <translation>第 %1 行不是廠商的 HI91 CSV 表頭（開頭為「%2」）</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>the header has no %1 column</source>
        <translation>表頭中沒有 %1 欄</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>line %1: the first column is &quot;%2&quot;, not HI91</source>
        <translation>第 %1 行：第一欄為「%2」，而不是 HI91</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>line %1 has %2 columns, the header %3</source>
        <translation>第 %1 行有 %2 欄，表頭有 %3 欄</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>line %1: %2 is not a number</source>
        <translation>第 %1 行：%2 不是數字</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>line %1: pc_counter %2 is not a time in ms</source>
        <translation>第 %1 行：pc_counter %2 不是以 ms 為單位的時間</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>the file is empty: no HI91 CSV header</source>
        <translation>檔案為空：沒有 HI91 CSV 表頭</translation>
    </message>
</context>
<context>
    <name>capture::McapRecording</name>
    <message>
        <location filename="../core/record/mcap_recorder.cpp" line="+113"/>
        <source>Recording to %1 stopped: %2. Check the free disk space.</source>
        <translation>錄製到 %1 已停止：%2。請檢查剩餘磁碟空間。</translation>
    </message>
</context>
<context>
    <name>imudesk::bridge::LiveBridge</name>
    <message>
        <location filename="../core/bridge/live_bridge.cpp" line="+173"/>
        <source>Cannot listen on %1 port %2: %3</source>
        <translation>無法在 %1 的連接埠 %2 上監聽：%3</translation>
    </message>
</context>
<context>
    <name>imudesk::calib::GyroCalSession</name>
    <message>
        <location filename="../core/calib/gyro_cal_session.cpp" line="+24"/>
        <source>The angle must be %1..%2 deg (2 to 5 turns); %3 is not.</source>
        <translation>角度必須在 %1..%2 deg 之間（2 至 5 圈）；%3 不符合。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>A gyro calibration is already running.</source>
        <translation>陀螺儀校準已在進行中。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Starting the gyro calibration (%1 deg).</source>
        <translation>正在啟動陀螺儀校準（%1 deg）。</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Stopping the gyro calibration.</source>
        <translation>正在停止陀螺儀校準。</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>Turn the module %1 deg at an even 20-100 deg/s, then stop on the mark.</source>
        <translation>以 20-100 deg/s 的均勻轉速將模組轉動 %1 deg，然後停在標記處。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The device did not answer CONFIG USRCAL START: check the link.</source>
        <translation>裝置未回應 CONFIG USRCAL START：請檢查連線。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The device refused CONFIG USRCAL START %1 (%2).</source>
        <translation>裝置拒絕 CONFIG USRCAL START %1（%2）。</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The device accepted the calibration (OK).</source>
        <translation>裝置已接受校準（OK）。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The device did not answer CONFIG USRCAL STOP: check the link, then repeat.</source>
        <translation>裝置未回應 CONFIG USRCAL STOP：請檢查連線後重試。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The device rejected the run (ERR): the angle turned was not within 5 deg of %1 deg, or the rate was outside 20-100 deg/s or uneven. Repeat it.</source>
        <translation>裝置拒絕本輪結果（ERR）：轉動角度與 %1 deg 相差超過 5 deg，或轉速超出 20-100 deg/s 或不均勻。請重做。</translation>
    </message>
</context>
<context>
    <name>imudesk::device::CanFamily</name>
    <message>
        <location filename="../core/device/can_family.cpp" line="+62"/>
        <source>connected to %1</source>
        <translation>已連線到 %1</translation>
    </message>
    <message>
        <location line="+10"/>
        <location line="+4"/>
        <source>the session was closed</source>
        <translation>連線已關閉</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>could not send frame %1: the CAN interface is not connected</source>
        <translation>無法傳送幀 %1：CAN 介面未連線</translation>
    </message>
    <message>
        <location line="+67"/>
        <source>boot-up</source>
        <translation>開機訊息</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>heartbeat</source>
        <translation>心跳</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>data</source>
        <translation>資料</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>SDO scan</source>
        <translation>SDO 掃描</translation>
    </message>
    <message>
        <location line="+41"/>
        <source>too many requests are waiting; try again when they are done</source>
        <translation>等待中的請求過多；請待其完成後再試</translation>
    </message>
    <message>
        <location line="+65"/>
        <source>no node answered &quot;%1&quot; to every node (address 255) within %2 ms: check the bit rate and the wiring</source>
        <translation>%2 ms 內沒有節點回應發往所有節點（位址 255）的「%1」：請檢查鮑率與接線</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>node %1 sent no data before &quot;%2&quot; either, so its effect cannot be seen: check the node ID</source>
        <translation>節點 %1 在「%2」之前也沒有傳送資料，因此看不到其效果：請檢查節點 ID</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>node %1 sent no data within %2 ms of &quot;%3&quot;: if its TPDOs wait for SYNC, send one; otherwise check the node ID, its output intervals and that the module is powered</source>
        <translation>節點 %1 在「%3」後 %2 ms 內沒有傳送資料：如果其 TPDO 等待 SYNC，請傳送一個；否則請檢查節點 ID、輸出間隔以及模組是否上電</translation>
    </message>
    <message>
        <location line="+94"/>
        <source>node %1 still sends data after &quot;%2&quot;: check the node ID</source>
        <translation>節點 %1 在「%2」之後仍在傳送資料：請檢查節點 ID</translation>
    </message>
    <message>
        <location line="-101"/>
        <source>no answer within %1 ms: node %2 sent no PGN %3 after &quot;%4&quot; (a PGN its firmware or configuration does not send, or output off)</source>
        <translation>%1 ms 內沒有回應：節點 %2 在「%4」之後沒有傳送 PGN %3（韌體或設定不傳送該 PGN，或輸出已關閉）</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>no answer from node %1 to &quot;%2&quot; within %3 ms: check the node ID, the bit rate and the wiring</source>
        <translation>節點 %1 在 %3 ms 內未回應「%2」：請檢查節點 ID、位元速率和接線</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>could not send &quot;%1&quot;: the CAN interface is not connected</source>
        <translation>無法傳送「%1」：CAN 介面未連線</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>the device refused &quot;%1&quot; (status %2)</source>
        <translation>裝置拒絕了「%1」（狀態 %2）</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>the device aborted &quot;%1&quot;: %2</source>
        <translation>裝置中止了「%1」：%2</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>the device refused &quot;%1&quot;: %2</source>
        <translation>裝置拒絕了「%1」：%2</translation>
    </message>
    <message>
        <location line="+58"/>
        <source>&quot;%1&quot; read back %2, expected %3</source>
        <translation>「%1」回讀值為 %2，預期為 %3</translation>
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
        <translation>%1 失敗：%2</translation>
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
        <translation>暫存器存取需要 J1939 裝置</translation>
    </message>
    <message>
        <location line="-6"/>
        <source>read register 0x%1</source>
        <translation>讀取暫存器 0x%1</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>read register</source>
        <translation>讀取暫存器</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>write register 0x%1</source>
        <translation>寫入暫存器 0x%1</translation>
    </message>
    <message>
        <location line="-3"/>
        <source>write register</source>
        <translation>寫入暫存器</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>SDO read</source>
        <translation>SDO 讀取</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>SDO write</source>
        <translation>SDO 寫入</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>read %1</source>
        <translation>讀取 %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+20"/>
        <source>%1 cannot be read: %2</source>
        <translation>%1 無法讀取：%2</translation>
    </message>
    <message>
        <location line="-16"/>
        <location line="+28"/>
        <source>%1 is a J1939 register: the device speaks another protocol</source>
        <translation>%1 是 J1939 暫存器：裝置使用的是其他協定</translation>
    </message>
    <message>
        <location line="-18"/>
        <location line="+29"/>
        <source>%1 is a CANopen object: the device speaks another protocol</source>
        <translation>%1 是 CANopen 物件：裝置使用的是其他協定</translation>
    </message>
    <message>
        <location line="-16"/>
        <source>%1 is read only</source>
        <translation>%1 為唯讀</translation>
    </message>
    <message>
        <location line="+9"/>
        <location line="+8"/>
        <source>read back %1</source>
        <translation>讀回 %1</translation>
    </message>
    <message>
        <location line="-6"/>
        <location line="+8"/>
        <source>%1 = %2, verified by reading it back</source>
        <translation>%1 = %2，已讀回校驗</translation>
    </message>
    <message>
        <location line="-11"/>
        <location line="+4"/>
        <location line="+8"/>
        <location line="+11"/>
        <source>write %1</source>
        <translation>寫入 %1</translation>
    </message>
    <message>
        <location line="-4"/>
        <source>%1 is an HEC495 object: the device speaks another protocol</source>
        <translation>%1 是 HEC495 物件：裝置使用的是其他協定</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: the HEC495 takes one byte</source>
        <translation>%1：HEC495 只接受一個位元組</translation>
    </message>
    <message>
        <location line="-22"/>
        <location line="+23"/>
        <source>%1 = %2, confirmed by the module&apos;s reply (it cannot be read back)</source>
        <translation>%1 = %2，已由模組應答確認（無法讀回）</translation>
    </message>
    <message>
        <location line="-125"/>
        <source>read the firmware version</source>
        <translation>讀取韌體版本</translation>
    </message>
    <message>
        <location line="+17"/>
        <source> (object 0x%1, firmware %2.%3.%4)</source>
        <translation>（物件 0x%1，韌體 %2.%3.%4）</translation>
    </message>
    <message>
        <location line="+5"/>
        <source> (object 0x%1: the module reports no firmware version)</source>
        <translation>（物件 0x%1：模組未回報韌體版本）</translation>
    </message>
    <message>
        <location line="+106"/>
        <source>%1 cannot be written</source>
        <translation>%1 無法寫入</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>0x%1 is not a data PGN</source>
        <translation>0x%1 不是資料 PGN</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the interval must be %1 to %2 ms</source>
        <translation>間隔必須為 %1 到 %2 ms</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>read back the interval</source>
        <translation>回讀間隔</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>PGN %1 interval %2 ms</source>
        <translation>PGN %1 間隔 %2 ms</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>set the interval</source>
        <translation>設定間隔</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>TPDO channel 0..5 and a period of 0..65535 ms, please</source>
        <translation>請指定 TPDO 通道 0..5 和 0..65535 ms 的週期</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>read back the TPDO period</source>
        <translation>回讀 TPDO 週期</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>TPDO%1 period %2 ms</source>
        <translation>TPDO%1 週期 %2 ms</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>set the TPDO period</source>
        <translation>設定 TPDO 週期</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the HEC495 has one PDO rate: use setHec495Rate</source>
        <translation>HEC495 只有一個 PDO 頻率：請使用 setHec495Rate</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+70"/>
        <location line="+30"/>
        <location line="+123"/>
        <source>the protocol is not known yet: choose it or wait for traffic</source>
        <translation>尚未得知協定：請選擇協定或等待匯流排上的資料</translation>
    </message>
    <message>
        <location line="-217"/>
        <source>the HEC495 rate code is 0 (off) to 6 (100 Hz)</source>
        <translation>HEC495 頻率代碼為 0（關閉）到 6（100 Hz）</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>SYNC mode needs a CANopen device and a TPDO channel 0..5</source>
        <translation>SYNC 模式需要 CANopen 裝置和 TPDO 通道 0..5</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>read back the transmission type</source>
        <translation>回讀傳輸類型</translation>
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
        <translation>非同步模式</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>set the transmission type</source>
        <translation>設定傳輸類型</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>the HEC495&apos;s heartbeat is 100 ms x (N + 1): %1 to %2 ms (it cannot be turned off)</source>
        <translation>HEC495 的心跳週期為 100 ms ×（N + 1）：%1 至 %2 ms（無法關閉）</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the heartbeat needs a CANopen or HEC495 device and 0..65535 ms</source>
        <translation>心跳需要 CANopen 或 HEC495 裝置以及 0..65535 ms</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>read back the heartbeat period</source>
        <translation>回讀心跳週期</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>heartbeat %1 ms</source>
        <translation>心跳 %1 ms</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>set the heartbeat</source>
        <translation>設定心跳</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the node ID must be 1..127</source>
        <translation>節點 ID 必須在 1..127 之間</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>traffic from node %1</source>
        <translation>來自節點 %1 的流量</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>node ID %1</source>
        <translation>節點 ID %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+8"/>
        <location line="+182"/>
        <source>reset</source>
        <translation>重設</translation>
    </message>
    <message>
        <location line="-189"/>
        <location line="+5"/>
        <location line="+8"/>
        <source>set the node ID</source>
        <translation>設定節點 ID</translation>
    </message>
    <message>
        <location line="-12"/>
        <location line="+5"/>
        <location line="+28"/>
        <location line="+2"/>
        <source>save</source>
        <translation>儲存</translation>
    </message>
    <message>
        <location line="-24"/>
        <source>traffic from node %1 (power-cycle the HEC495 now)</source>
        <translation>來自節點 %1 的流量（請立即將 HEC495 斷電重啟）</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>HiPNUC J1939 modules support 125000, 250000, 500000, 800000 and 1000000 bit/s</source>
        <translation>HiPNUC J1939 模組支援 125000、250000、500000、800000 和 1000000 bit/s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the CANopen object 0x209A takes 125000, 250000, 500000 and 1000000 bit/s (800000 is a J1939 rate only)</source>
        <translation>CANopen 物件 0x209A 僅接受 125000、250000、500000 和 1000000 bit/s（800000 僅適用於 J1939）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>CAN bit rate %1 (saved; takes effect after a reset: reopen the session at that rate)</source>
        <translation>CAN 位元速率 %1（已儲存；重設後生效：請以該速率重新連線）</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+2"/>
        <location line="+8"/>
        <source>set the bit rate</source>
        <translation>設定位元速率</translation>
    </message>
    <message>
        <location line="-2"/>
        <source>the HEC495 supports 10000 to 500000 bit/s (see its manual&apos;s table)</source>
        <translation>HEC495 支援 10000 至 500000 位元/秒（見其手冊中的表格）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CAN bit rate %1 (takes effect after a power cycle: reopen the session at that rate)</source>
        <translation>CAN 位元速率 %1（斷電重啟後生效：請以該速率重新連線）</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>attitude reset mode 1, 2, 3 or 5, please</source>
        <translation>姿態重設模式請用 1、2、3 或 5</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>attitude reset %1</source>
        <translation>姿態重設 %1</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>attitude reset</source>
        <translation>姿態重設</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>CANopen zeroing: mode 2 (set zero) or 5 (clear), please</source>
        <translation>CANopen 置零：請用模式 2（設定零點）或 5（清除零點）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>zero %1</source>
        <translation>置零 %1</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>set zero</source>
        <translation>設定零點</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>attitude reset needs a HiPNUC J1939 or CANopen device</source>
        <translation>姿態重設需要 HiPNUC J1939 或 CANopen 裝置</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the inclinometer axis is X (0) or Y (1)</source>
        <translation>傾角儀軸為 X（0）或 Y（1）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>inclinometer %1 %2</source>
        <translation>傾角儀 %1 %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>reversed</source>
        <translation>反向</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>default direction</source>
        <translation>預設方向</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+6"/>
        <source>read back the inclinometer sign</source>
        <translation>回讀傾角儀正負方向</translation>
    </message>
    <message>
        <location line="-4"/>
        <location line="+6"/>
        <source>set the inclinometer sign</source>
        <translation>設定傾角儀正負方向</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the inclinometer sign needs a HiPNUC J1939 or CANopen device</source>
        <translation>傾角儀正負方向需要 HiPNUC J1939 或 CANopen 裝置</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the PDO mode is an HEC495 setting</source>
        <translation>PDO 模式是 HEC495 的設定</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the extended variant&apos;s PDO format is 0 (X) or 1 (X and Y)</source>
        <translation>擴展幀方式的 PDO 格式為 0（X）或 1（X 和 Y）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the PDO mode is 0 (float), 1 (fixed point) or 3 (float, 0x180 and 0x280 only)</source>
        <translation>PDO 模式為 0（浮點）、1（定點）或 3（浮點，僅 0x180 和 0x280）</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>the work mode is an HEC495 setting on standard frames</source>
        <translation>工作模式是 HEC495 標準幀方式的設定</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the work mode is 0x02 (pitch, roll, acceleration, rate) or 0x0A (rate at 500 Hz)</source>
        <translation>工作模式為 0x02（俯仰、橫滾、加速度、角速度）或 0x0A（以 500 Hz 輸出角速度）</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>output on or off for every node needs CANopen or an HEC495 on standard frames (NMT)</source>
        <translation>對所有節點開關輸出需要 CANopen 或標準幀方式的 HEC495（NMT）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>NMT start, every node</source>
        <translation>NMT 啟動，所有節點</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>NMT stop, every node</source>
        <translation>NMT 停止，所有節點</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>output on</source>
        <translation>開啟輸出</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>output off</source>
        <translation>關閉輸出</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>output enable</source>
        <translation>輸出啟用</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>NMT start</source>
        <translation>NMT 啟動</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>NMT stop</source>
        <translation>NMT 停止</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>&quot;%1&quot; needs a HiPNUC J1939 or CANopen device (the HEC495 saves at once)</source>
        <translation>「%1」需要 HiPNUC J1939 或 CANopen 裝置（HEC495 會立即儲存）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>save configuration</source>
        <translation>儲存配置</translation>
    </message>
    <message>
        <location line="+8"/>
        <location line="+1"/>
        <location line="+8"/>
        <source>factory defaults</source>
        <translation>恢復出廠設定</translation>
    </message>
    <message>
        <location line="-2"/>
        <source> (firmware 1.6: they take effect at the next power-up)</source>
        <translation>（韌體 1.6：下次上電後生效）</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>a one-shot trigger needs a J1939 device and a data PGN</source>
        <translation>單次觸發需要 J1939 裝置和資料 PGN</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>trigger PGN %1</source>
        <translation>觸發 PGN %1</translation>
    </message>
</context>
<context>
    <name>imudesk::device::GroupRecording</name>
    <message>
        <location filename="../core/record/group_recording.cpp" line="+47"/>
        <source>A session recording is already running.</source>
        <translation>工作階段錄製已在進行中。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>No device to record: connect one first.</source>
        <translation>沒有可錄製的裝置：請先連線一台裝置。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 already holds a recorded session; choose another folder.</source>
        <translation>%1 中已有錄製的工作階段；請選擇其他資料夾。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Cannot create the folder %1: check that the place exists and can be written to.</source>
        <translation>無法建立資料夾 %1：請確認該位置存在且可寫入。</translation>
    </message>
    <message>
        <location line="+57"/>
        <source>The device&apos;s tab was closed or its link replaced; its capture ends here.</source>
        <translation>該裝置的分頁已關閉或其連線已被取代；其記錄到此結束。</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>None of the devices could be recorded: %1.</source>
        <translation>所有裝置皆無法錄製：%1。</translation>
    </message>
    <message>
        <location line="+49"/>
        <source>Stopped in the device&apos;s own tab (Record or Disconnect) before the session ended.</source>
        <translation>工作階段結束前已在該裝置自己的分頁中停止（錄製或中斷連線）。</translation>
    </message>
</context>
<context>
    <name>imudesk::device::Hec495Family</name>
    <message>
        <location filename="../core/device/hec495_family.cpp" line="+66"/>
        <source>the request&apos;s data is longer than a Witlink frame can carry</source>
        <translation>請求的資料超過 Witlink 幀可承載的長度</translation>
    </message>
    <message>
        <location line="+44"/>
        <source>no HEC495 answered on %1 at %2 baud: check the wiring (RS-232 TXD/RXD or RS-485 A/B), the power, the baud rate and the module address (%3)</source>
        <translation>%1 上沒有 HEC495 以波特率 %2 回應：請檢查接線（RS-232 TXD/RXD 或 RS-485 A/B）、電源、波特率和模組位址（%3）</translation>
    </message>
    <message>
        <location line="-1"/>
        <source>any supported</source>
        <translation>任一支援值</translation>
    </message>
    <message>
        <location line="+80"/>
        <source>no reply to &quot;%1&quot; after %2 attempts of %3 ms (check the baud rate and the module address; an RS-485 module that streams may miss commands: set question/answer mode)</source>
        <translation>嘗試 %2 次（每次 %3 ms）後仍未收到「%1」的回應（請檢查波特率和模組位址；持續輸出資料的 RS-485 模組可能漏收指令：請設為問答模式）</translation>
    </message>
    <message>
        <location line="+160"/>
        <source>the module answered with an invalid reply: %1</source>
        <translation>模組的回應無效：%1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the module reported failure (FF) for &quot;%1&quot;</source>
        <translation>模組回報「%1」失敗（FF）</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>the module streams: identified without a request</source>
        <translation>模組正在持續輸出：無需請求即已識別</translation>
    </message>
</context>
<context>
    <name>imudesk::device::Hec495Session</name>
    <message>
        <location filename="../core/device/hec495_session.cpp" line="+77"/>
        <source>the declination must be between -99.9 and 99.9 degrees (got %1)</source>
        <translation>磁偏角必須在 -99.9 到 99.9 度之間（收到 %1）</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>the HEC495 supports 2400, 4800, 9600, 19200 and 115200 baud (got %1)</source>
        <translation>HEC495 支援的波特率為 2400、4800、9600、19200 和 115200（收到 %1）</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>the output rate must be 0 (question/answer), 5, 10, 15, 25, 50 or 100 Hz (got %1)</source>
        <translation>輸出速率必須為 0（問答模式）、5、10、15、25、50 或 100 Hz（收到 %1）</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the output content must be 0 to 3</source>
        <translation>輸出內容必須為 0 至 3</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the address must be 0 to 255 (got %1)</source>
        <translation>位址必須為 0 至 255（收到 %1）</translation>
    </message>
</context>
<context>
    <name>imudesk::device::HipnucSerialFamily</name>
    <message>
        <location filename="../core/device/hipnuc_family.cpp" line="+202"/>
        <source>The device that came back on %1 is a different one (serial %2, before %3). Its data continues in this session.</source>
        <translation>%1 上重新出現的是另一台裝置（序號 %2，之前為 %3）。其資料將繼續記錄在此工作階段中。</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>no reply within %1 ms (the device ignores commands it does not know)</source>
        <translation>%1 ms 內無回應（裝置不回應它不認識的指令）</translation>
    </message>
    <message>
        <location filename="../core/device/hipnuc_family_baud.cpp" line="+66"/>
        <source>No HiPNUC device answered on %1 at any baud rate (115200, 921600, 460800, 230400, 256000, 57600, 38400, 19200, 9600, 4800). Check the cable and the power, and that no other program uses the port.</source>
        <translation>%1 上在所有波特率（115200、921600、460800、230400、256000、57600、38400、19200、9600、4800）下都沒有 HiPNUC 裝置回應。請檢查線材和電源，並確認沒有其他程式占用該串列埠。</translation>
    </message>
    <message>
        <location line="-20"/>
        <source>trying %1 baud</source>
        <translation>正在嘗試 %1 波特率</translation>
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
        <translation>串列埠未開啟</translation>
    </message>
    <message>
        <location line="-32"/>
        <source>the device refused SERIALCONFIG %1 (%2) and stays at %3 baud</source>
        <translation>裝置拒絕了 SERIALCONFIG %1（%2），仍維持波特率 %3</translation>
    </message>
    <message>
        <location line="+11"/>
        <location line="+36"/>
        <source>the device answers at %1 baud</source>
        <translation>裝置在波特率 %1 下回應</translation>
    </message>
    <message>
        <location line="-31"/>
        <source>the device did not answer at %1 baud; it answers at %2 baud</source>
        <translation>裝置在波特率 %1 下無回應；改在波特率 %2 下回應</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the device answers neither at %1 nor at %2 baud nor at any other rate: check the cable and power-cycle it</source>
        <translation>裝置在波特率 %1、%2 及其他任何速率下均無回應：請檢查纜線，並將裝置斷電重啟</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>the device does not answer at any baud rate</source>
        <translation>裝置在任何波特率下均無回應</translation>
    </message>
</context>
<context>
    <name>imudesk::device::LinkOpener</name>
    <message>
        <location filename="../core/links/link_opener.cpp" line="+118"/>
        <source>%1: no serial device family is called &quot;%2&quot;</source>
        <translation>%1：沒有名為「%2」的序列埠裝置系列</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>The simulated Modbus device could not start: %1</source>
        <translation>模擬 Modbus 裝置無法啟動：%1</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>The simulated CAN device could not start on %1:%2: %3</source>
        <translation>模擬 CAN 裝置無法在 %1:%2 上啟動：%3</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>A capture file cannot be simulated.</source>
        <translation>擷取檔案無法模擬。</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1: the device&apos;s family is found by a detection, which does not finish at once</source>
        <translation>%1：裝置系列需要偵測才能確定，偵測不會立即完成</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>%1 cannot be read. Check that the file exists and that you may read it.</source>
        <translation>無法讀取 %1。請確認檔案存在且您有讀取權限。</translation>
    </message>
    <message>
        <location line="+78"/>
        <source>the port of %1 was lost while it was handed to the device&apos;s session</source>
        <translation>%1 的連接埠在交給裝置工作階段時遺失</translation>
    </message>
</context>
<context>
    <name>imudesk::device::ModbusSession</name>
    <message>
        <location filename="../core/device/modbus_session.cpp" line="+95"/>
        <source>ILLEGAL FUNCTION (01): the device does not support this request at %1.</source>
        <translation>ILLEGAL FUNCTION（01）：裝置不支援對 %1 的此項請求。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>ILLEGAL DATA ADDRESS (02): %1 does not exist on this device or cannot be accessed this way (write-only or read-only). Check the register map of the device&apos;s manual.</source>
        <translation>ILLEGAL DATA ADDRESS（02）：%1 在此裝置上不存在，或無法以此方式存取（唯寫或唯讀）。請查閱裝置手冊中的暫存器表。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>ILLEGAL DATA VALUE (03): the device refused the value or count for %1. Check the register&apos;s range.</source>
        <translation>ILLEGAL DATA VALUE（03）：裝置拒絕了 %1 的數值或數量。請檢查該暫存器的範圍。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>SERVER DEVICE FAILURE (04): the device failed while handling %1. Reset it and try again.</source>
        <translation>SERVER DEVICE FAILURE（04）：裝置處理 %1 時發生故障。請重設裝置後再試。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>SERVER DEVICE BUSY (06): the device is busy; try %1 again later.</source>
        <translation>SERVER DEVICE BUSY（06）：裝置忙碌中；請稍後再試 %1。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Modbus exception %1 at %2.</source>
        <translation>%2 發生 Modbus 例外 %1。</translation>
    </message>
    <message>
        <location filename="../core/device/modbus_family.cpp" line="+119"/>
        <source>Port open at %1 baud</source>
        <translation>串列埠已開啟，波特率 %1</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>The serial port %1 cannot run at %2 baud. Connect again at the device&apos;s new rate.</source>
        <translation>串列埠 %1 無法以 %2 波特率運作。請以裝置的新波特率重新連線。</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>a Modbus node ID is 0 to 247 (got %1)</source>
        <translation>Modbus 節點 ID 應為 0 到 247（收到 %1）</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>register 0x%1</source>
        <translation>暫存器 0x%1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>No reply from node %1 at %2 baud within %3 ms. Check the node ID, the baud rate and parity, and the RS-485 wiring (A/B).</source>
        <translation>節點 %1 在波特率 %2 下 %3 ms 內無回應。請檢查節點 ID、波特率和同位檢查，以及 RS-485 接線（A/B）。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The request to node %1 failed: %2</source>
        <translation>對節點 %1 的請求失敗：%2</translation>
    </message>
    <message>
        <location line="+93"/>
        <source>the reply carries another number of registers than asked for</source>
        <translation>回應中的暫存器數量與請求的不一致</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Reading the identity of node %1</source>
        <translation>正在讀取節點 %1 的身分資訊</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>Modbus node %1</source>
        <translation>Modbus 節點 %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Node %1 at %2 baud</source>
        <translation>節點 %1，波特率 %2</translation>
    </message>
    <message>
        <location line="+58"/>
        <source>Node %1 answers again</source>
        <translation>節點 %1 已恢復回應</translation>
    </message>
    <message>
        <location line="+42"/>
        <source>not connected</source>
        <translation>未連線</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a read takes 1 to 125 registers</source>
        <translation>每次讀取須為 1 至 125 個暫存器</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Not connected: connect first.</source>
        <translation>未連線：請先連線。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 is not a valid value for %2 (%3).</source>
        <translation>%1 不是 %2 的有效值（%3）。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Register address and value must be 0..65535.</source>
        <translation>暫存器位址和數值必須在 0..65535 之間。</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>Done: %1.</source>
        <translation>完成：%1。</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Written, but reading it back failed: %1</source>
        <translation>已寫入，但回讀失敗：%1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Written, but the device reads back %1 instead of %2.</source>
        <translation>已寫入，但裝置回讀值為 %1，而非 %2。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Read back: %1.</source>
        <translation>回讀值：%1。</translation>
    </message>
    <message>
        <location line="+99"/>
        <source>The serial port %1 cannot run at %2 baud.</source>
        <translation>串列埠 %1 無法以 %2 波特率運作。</translation>
    </message>
    <message>
        <location line="+43"/>
        <source>HEC495 compass (pitch %1 deg)</source>
        <translation>HEC495 羅盤（俯仰角 %1 deg）</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>answers, identity unreadable</source>
        <translation>有回應，但無法讀取身分資訊</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>The serial port %1 cannot return to %2 baud.</source>
        <translation>串列埠 %1 無法恢復到 %2 波特率。</translation>
    </message>
    <message>
        <location line="-43"/>
        <source>answers with Modbus exception %1</source>
        <translation>回應 Modbus 例外 %1</translation>
    </message>
</context>
<context>
    <name>imudesk::device::SerialFamilyScan</name>
    <message>
        <location filename="../core/links/serial_family_scan.cpp" line="+52"/>
        <source>trying %1 baud</source>
        <translation>正在嘗試 %1 鮑率</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>no device answered on %1 at %2 baud (looked for %3): check the power, the wiring and that no other program holds the port</source>
        <translation>%1 在 %2 鮑率下沒有裝置回應（尋找的是 %3）：請檢查電源、接線，以及連接埠是否被其他程式佔用</translation>
    </message>
    <message>
        <location line="+2"/>
        <source> or </source>
        <translation> 或 </translation>
    </message>
    <message>
        <location filename="../core/links/serial_family_scan.h" line="+37"/>
        <source>serial</source>
        <translation>序列埠</translation>
    </message>
</context>
<context>
    <name>imudesk::device::SessionEngine</name>
    <message>
        <location filename="../core/device/session_engine.cpp" line="+133"/>
        <source>the link went to the device&apos;s own session</source>
        <translation>連結已交給裝置自己的工作階段</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>the connection was closed</source>
        <translation>連線已關閉</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>disconnected — waiting for the device to come back</source>
        <translation>已中斷連線，正在等待裝置重新連線</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>automatic reconnection was turned off</source>
        <translation>自動重新連線已關閉</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1 at %2 baud (reconnected)</source>
        <translation>%1，波特率 %2（已重新連線）</translation>
    </message>
    <message>
        <location line="+56"/>
        <source>the port is not open</source>
        <translation>串列埠未開啟</translation>
    </message>
    <message>
        <location line="+55"/>
        <source>writing to the port failed</source>
        <translation>寫入串列埠失敗</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>no reply within %1 ms</source>
        <translation>%1 ms 內沒有回應</translation>
    </message>
    <message>
        <location line="+75"/>
        <source>Bytes keep arriving on %1 but none of them form a frame: the device probably runs at another baud rate now. Disconnect and connect again with the baud rate set to Auto.</source>
        <translation>%1 上持續收到位元組，但無法組成任何資料框：裝置可能已改用其他波特率。請中斷連線，並將波特率設為「自動」後重新連線。</translation>
    </message>
</context>
<context>
    <name>imudesk::discovery::BenchSweep</name>
    <message>
        <location filename="../core/discovery/bench_sweep.cpp" line="+120"/>
        <source>looking for a serial device</source>
        <translation>正在尋找序列埠裝置</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>no serial device answered; as a Modbus line %1 of %2 addresses and rates were asked before the time was up (nothing answered): give the sweep more time</source>
        <translation>沒有序列埠裝置回應；作為 Modbus 線路，在時間用完前已詢問 %2 個位址與鮑率組合中的 %1 個（均無回應）：請給掃描更多時間</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the sweep was cancelled while the port was asked as a Modbus line</source>
        <translation>該連接埠作為 Modbus 線路詢問期間掃描被取消</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the time was up before anything answered</source>
        <translation>在有裝置回應之前時間已用完</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+257"/>
        <source>the sweep was cancelled</source>
        <translation>掃描已取消</translation>
    </message>
    <message>
        <location line="-238"/>
        <source>%1 at %2 baud: reading its identity</source>
        <translation>%1，鮑率 %2：正在讀取其身分資訊</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>the sweep ended before it said who it is</source>
        <translation>掃描在其回報身分之前已結束</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>it streams, but did not say who it is within %1 s</source>
        <translation>裝置在輸出資料，但 %1 s 內未回報其身分</translation>
    </message>
    <message>
        <location line="+59"/>
        <source>asking it as a Modbus RTU line</source>
        <translation>正在作為 Modbus RTU 線路詢問</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>known by its answer at the angle registers (no identity block)</source>
        <translation>依其角度暫存器的回應識別（無身分資訊區塊）</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1 replies to id %2 failed their CRC while other ids&apos; replies were whole: two devices answering at once garble each other</source>
        <translation>發往 ID %2 的回應中有 %1 個 CRC 檢查失敗，而其他 ID 的回應完好：兩台裝置同時回應，相互干擾</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Connect the devices one at a time and give each its own Modbus id (Settings, MD_ID; save and reset), then sweep again.</source>
        <translation>逐台連接裝置，並為每台設定各自的 Modbus ID（設定中的 MD_ID，儲存並重設），然後重新掃描。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Modbus id %1 answers at %2 baud</source>
        <translation>Modbus ID %1 在鮑率 %2 下回應</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>%1 bytes arrived but none formed a frame of any family at any rate%2: check the wiring (A/B swapped on RS-485, TX/RX), the parity and that the device is one ImuDesk knows</source>
        <translation>收到 %1 位元組，但在任何鮑率下都不構成任何裝置系列的封包%2：請檢查接線（RS-485 的 A/B 是否接反、TX/RX）、同位檢查，以及該裝置是否為 ImuDesk 支援的裝置</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>, nor a Modbus reply</source>
        <translation>，也不是 Modbus 回應</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>nothing answered at any rate%1: check the power and the wiring, or that a device is connected at all</source>
        <translation>在任何鮑率下均無回應%1：請檢查電源和接線，或確認是否連接了裝置</translation>
    </message>
    <message>
        <location line="+2"/>
        <source> (serial families and Modbus ids 1-247)</source>
        <translation>（序列埠裝置系列及 Modbus ID 1-247）</translation>
    </message>
    <message>
        <location line="+62"/>
        <source>the time was up before the bus was heard at every bit rate</source>
        <translation>尚未在所有鮑率下監聽匯流排，時間已用完</translation>
    </message>
    <message>
        <location line="+49"/>
        <source>%1 bit/s</source>
        <translation>%1 bit/s</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>the interface&apos;s rate</source>
        <translation>介面目前的鮑率</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>errors at every bit rate tried (%1): check the termination (120 Ω at each end), CAN-H/CAN-L and the ground; nothing was sent on this bus</source>
        <translation>嘗試的每個鮑率（%1）下都有錯誤：請檢查終端電阻（兩端各 120 Ω）、CAN-H/CAN-L 和接地；未向該匯流排送出任何訊息</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>listening at %1</source>
        <translation>正在以 %1 監聽</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>asking the nodes at %1</source>
        <translation>正在以 %1 詢問各節點</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>Qt&apos;s virtualcan interface has no bit rate</source>
        <translation>Qt 的 virtualcan 介面沒有鮑率</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1 frames at %2, none of a device ImuDesk knows, and nothing answered</source>
        <translation>以 %2 收到 %1 個訊框，均不屬於 ImuDesk 支援的裝置，且無回應</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>no traffic at any bit rate (%1) and nothing answered when asked at %2: check the power and the wiring</source>
        <translation>在任何鮑率（%1）下均無訊息，以 %2 詢問時也無回應：請檢查電源和接線</translation>
    </message>
</context>
<context>
    <name>imudesk::discovery::SimulatedBench</name>
    <message>
        <location filename="../core/discovery/simulated_bench.cpp" line="+25"/>
        <source>%1 could not start: %2</source>
        <translation>%1 無法啟動：%2</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>A simulated serial device</source>
        <translation>一個模擬序列埠裝置</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The simulated Modbus module</source>
        <translation>模擬 Modbus 模組</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>A simulated CAN module</source>
        <translation>一個模擬 CAN 模組</translation>
    </message>
</context>
<context>
    <name>imudesk::io::CanTransport</name>
    <message>
        <location filename="../core/io/can_transport.cpp" line="+75"/>
        <source>the CAN plugin &quot;%1&quot; is not installed (available: %2)</source>
        <translation>未安裝 CAN 外掛程式「%1」（可用：%2）</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>cannot create CAN interface %1: %2</source>
        <translation>無法建立 CAN 介面 %1：%2</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>CAN interface error: %1</source>
        <translation>CAN 介面錯誤：%1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the CAN interface %1 closed; received data is kept</source>
        <translation>CAN 介面 %1 已關閉；已接收的資料會保留</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>cannot open CAN interface %1: %2 (check the interface name, that it is up, and your permissions)</source>
        <translation>無法開啟 CAN 介面 %1：%2（請檢查介面名稱、介面是否已啟用以及存取權限）</translation>
    </message>
    <message>
        <location line="+49"/>
        <source>frames written while the CAN interface %1 was connecting could not be sent</source>
        <translation>CAN 介面 %1 連線期間寫入的訊框未能送出</translation>
    </message>
</context>
<context>
    <name>imudesk::io::SerialTransport</name>
    <message>
        <location filename="../core/io/serial_transport.cpp" line="+28"/>
        <source>Port %1 was not found. Check that the device is plugged in and choose the port again from the list.</source>
        <translation>找不到串列埠 %1。請檢查裝置是否已插好，然後從清單中重新選擇串列埠。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Port %1 is in use by another program (a serial terminal, CHCenter or another ImuDesk). Close that program and connect again.</source>
        <translation>串列埠 %1 正被其他程式占用（序列終端機、CHCenter 或另一個 ImuDesk）。請關閉該程式後重新連線。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>No permission to open %1. On Linux add your user to the dialout group (sudo usermod -aG dialout $USER), then log out and in again; or install the udev rule that docs/INSTALLING.md describes (60-imudesk-serial.rules).</source>
        <translation>沒有開啟 %1 的權限。在 Linux 上請將使用者加入 dialout 群組（sudo usermod -aG dialout $USER），然後登出再重新登入；或安裝 docs/INSTALLING.md 中所述的 udev 規則（60-imudesk-serial.rules）。</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Could not open %1: %2</source>
        <translation>無法開啟 %1：%2</translation>
    </message>
    <message>
        <location line="+225"/>
        <source>The connection to %1 was lost (%2). Check the cable; everything received so far is kept.</source>
        <translation>與 %1 的連線已中斷（%2）。請檢查線材；已接收的資料都會保留。</translation>
    </message>
</context>
<context>
    <name>imudesk::model::MainStatus</name>
    <message>
        <location filename="../core/model/main_status.cpp" line="+10"/>
        <source>HiPNUC manual v1.7.1, 5.9.13</source>
        <translation>HiPNUC 手冊 v1.7.1，5.9.13</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Gyro bias estimate not yet converged: keep the module still for 3-5 s to improve heading accuracy.</source>
        <translation>陀螺儀零偏估計尚未收斂：請保持模組靜止 3-5 s，以提高航向角精度。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Magnetic disturbance: the field is disturbed, the magnetometer is not calibrated or the hard-iron environment changed; 9-axis heading may be wrong.</source>
        <translation>磁場干擾：磁場受到干擾、磁力計未校準或硬磁環境發生變化；9 軸航向角可能不準確。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Accelerometer over range now or within the last 2 s.</source>
        <translation>加速度計目前或最近 2 s 內超出量程。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Gyroscope over range now or within the last 2 s.</source>
        <translation>陀螺儀目前或最近 2 s 內超出量程。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Attitude accuracy poor (large AHRS filter covariance): keep still for a moment.</source>
        <translation>姿態精度差（AHRS 濾波器共變異數較大）：請保持靜止片刻。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The device detected that it is static.</source>
        <translation>裝置偵測到自身處於靜止狀態。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the vendor&apos;s SDK; the v1.7.1 manual (5.9.13) lists bit 9 as reserved</source>
        <translation>廠商 SDK；v1.7.1 手冊（5.9.13）將第 9 位元列為保留</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The magnetometer takes part in heading (9-axis mode).</source>
        <translation>磁力計參與航向解算（9 軸模式）。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Not synchronised to UTC: system_time is time since power-up.</source>
        <translation>未與 UTC 同步：system_time 為上電以來的時間。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>HiPNUC manual v1.7.1, 5.9.13 (named UTC_SYNCED there, but 1 means not synchronised; the SDK calls it UTC_UNSYNC)</source>
        <translation>HiPNUC 手冊 v1.7.1，5.9.13（手冊中名為 UTC_SYNCED，但 1 表示未同步；SDK 稱其為 UTC_UNSYNC）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>This frame corresponds to a SYNC_OUT pulse.</source>
        <translation>該幀對應一個 SYNC_OUT 脈衝。</translation>
    </message>
</context>
<context>
    <name>imudesk::models::CalibrationHistoryModel</name>
    <message>
        <location filename="../core/itemmodels/calibration_history_model.cpp" line="+41"/>
        <source>Magnetometer</source>
        <translation>磁力計</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Gyro scale factor</source>
        <translation>陀螺儀標度因數</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Attitude reset</source>
        <translation>姿態重設</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Compass (HEC495)</source>
        <translation>羅盤（HEC495）</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>|B| %1 µT, fit error %2 %, coverage %3 %</source>
        <translation>|B| %1 µT，擬合誤差 %2 %，覆蓋率 %3 %</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>scale error %1 %</source>
        <translation>標度誤差 %1 %</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>Time</source>
        <translation>時間</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Calibration</source>
        <translation>校準</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Verdict</source>
        <translation>判定</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Result</source>
        <translation>結果</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Firmware</source>
        <translation>韌體</translation>
    </message>
</context>
<context>
    <name>imudesk::models::CanFrameMonitorModel</name>
    <message>
        <location filename="../core/itemmodels/can_frame_monitor_model.cpp" line="+32"/>
        <source>Ext</source>
        <translation>擴充</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Std</source>
        <translation>標準</translation>
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
        <translation> Tx</translation>
    </message>
    <message>
        <location line="+0"/>
        <source> Rx</source>
        <translation> Rx</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>CAN-ID</source>
        <translation>CAN-ID</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Type</source>
        <translation>類型</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Length</source>
        <translation>長度</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Data</source>
        <translation>資料</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cycle time (ms)</source>
        <translation>週期（ms）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Count</source>
        <translation>次數</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Meaning</source>
        <translation>含義</translation>
    </message>
    <message>
        <location line="+132"/>
        <source>cannot write %1: %2</source>
        <translation>無法寫入 %1：%2</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>writing %1 failed: %2 (is the disk full?)</source>
        <translation>寫入 %1 失敗：%2（磁碟是否已滿？）</translation>
    </message>
</context>
<context>
    <name>imudesk::models::ClockStatsModel</name>
    <message>
        <location filename="../core/itemmodels/clock_stats_model.cpp" line="+39"/>
        <source>device counter</source>
        <translation>裝置計數器</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>request/answer</source>
        <translation>請求/回應</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>receive stamp</source>
        <translation>接收時間戳記</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>aligned</source>
        <translation>已對齊</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>uncertain: fitting, %1 s of the %2 s it needs</source>
        <translation>不確定：擬合中，已有 %1 s，需要 %2 s</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>free-running: the interface gives no receive stamps</source>
        <translation>自由運行：介面不提供接收時間戳記</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>free-running: no device time yet</source>
        <translation>自由運行：尚無裝置時間</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>The device&apos;s own time, fitted against the host&apos;s clock from its least delayed samples</source>
        <translation>裝置自身的時間，由延遲最小的樣本對主機時鐘擬合而得</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>No device time: the sample was taken between the request and its answer; the middle is used</source>
        <translation>無裝置時間：取樣時刻位於請求與回應之間；取兩者的中點</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>No device time: the interface&apos;s receive stamp less the frame&apos;s time on the bus</source>
        <translation>無裝置時間：取介面的接收時間戳記減去該幀在匯流排上的傳輸時間</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>How fast the device&apos;s clock runs against the host&apos;s, in parts per million</source>
        <translation>裝置時鐘相對於主機時鐘的快慢，單位 ppm（百萬分之一）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Scatter of the least delayed samples about the fitted line, in ms</source>
        <translation>延遲最小的樣本相對於擬合直線的離散程度，單位 ms</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Half the request-to-answer time: the sampling instant lies within this, in ms</source>
        <translation>從請求到回應時間的一半：取樣時刻落在此範圍內，單位 ms</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Times the device&apos;s counter restarted or its time base changed (each starts the fit again)</source>
        <translation>裝置計數器重新啟動或其時間基準改變的次數（每次都會重新開始擬合）</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>Stream</source>
        <translation>資料流</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Time from</source>
        <translation>時間來源</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>State</source>
        <translation>狀態</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Drift (ppm)</source>
        <translation>漂移（ppm）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Jitter (ms)</source>
        <translation>抖動（ms）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>± (ms)</source>
        <translation>±（ms）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Resets</source>
        <translation>重設次數</translation>
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
        <translation>無效應答</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>timeout</source>
        <translation>逾時</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cancelled</source>
        <translation>已取消</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not sent</source>
        <translation>未傳送</translation>
    </message>
    <message>
        <location line="+50"/>
        <source>Time</source>
        <translation>時間</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Command</source>
        <translation>指令</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Status</source>
        <translation>狀態</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Reply</source>
        <translation>回應</translation>
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
        <translation>數值</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Unit</source>
        <translation>單位</translation>
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
        <translation>%1（%2 分鐘前）</translation>
    </message>
    <message>
        <location line="+101"/>
        <source>0 invalid</source>
        <translation>0 解無效</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>1 aligning</source>
        <translation>1 對準中</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>3 navigating</source>
        <translation>3 組合導航中</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>6 dead reckoning</source>
        <translation>6 慣性遞推中</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>0 no fix</source>
        <translation>0 未定位</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>1 single</source>
        <translation>1 單點定位</translation>
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
        <translation>5 RTK 浮點解</translation>
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
        <translation>無 (%1)</translation>
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
        <translation>裝置時間</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>INS status</source>
        <translation>組合導航狀態</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Latitude</source>
        <translation>緯度</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Longitude</source>
        <translation>經度</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Altitude (MSL)</source>
        <translation>海拔高度</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Velocity east</source>
        <translation>東向速度</translation>
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
        <translation>UTC 時間</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Heave</source>
        <translation>垂蕩</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Surge</source>
        <translation>縱蕩</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Sway</source>
        <translation>橫蕩</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Inclination X</source>
        <translation>X 軸傾角</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Inclination Y</source>
        <translation>Y 軸傾角</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>UTC date</source>
        <translation>UTC 日期</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Heave/surge/sway frequency</source>
        <translation>升沉/縱蕩/橫蕩頻率</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Acceleration E N U</source>
        <translation>加速度 東 北 天</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>GNSS heading fix</source>
        <translation>GNSS 航向解狀態</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Odometer speed</source>
        <translation>里程計速度</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Geoid undulation</source>
        <translation>高程異常</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Differential age</source>
        <translation>差分齡期</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Node ID</source>
        <translation>節點 ID</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Filter updates</source>
        <translation>濾波器量測更新</translation>
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
        <translation>GNSS 位置、速度標準差</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Dual antenna</source>
        <translation>雙天線</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>GNSS lat lon alt</source>
        <translation>GNSS 緯度 經度 高度</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>GNSS velocity E N U</source>
        <translation>GNSS 速度 東 北 天</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Status flags</source>
        <translation>狀態旗標</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Frame type</source>
        <translation>幀類型</translation>
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
        <translation>相對值</translation>
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
        <translation>沿感測器 %1 軸的加速度，單位 G（1 G = 9.8 m/s²，廠商採用的常數）。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Angular velocity about the sensor&apos;s %1 axis, in deg/s.</source>
        <translation>繞感測器 %1 軸的角速度，單位 °/s。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Magnetic field along the sensor&apos;s %1 axis, in µT.</source>
        <translation>沿感測器 %1 軸的磁場強度，單位 µT。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 angle, in degrees: Euler angles 3-1-2 in the North-West-Up frame the module is set to (CONFIG IMU COORD 4); the yaw is 0 with the module&apos;s Y axis pointing west.</source>
        <translation>%1角，單位為度：模組所設北西天座標系（CONFIG IMU COORD 4）下的 3-1-2 歐拉角；模組 Y 軸指向西時航向角為 0。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Roll</source>
        <translation>橫滾</translation>
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
        <translation>橫滾角，單位 °（裝置約定的歐拉角，預設 ENU 312 順序）。</translation>
    </message>
    <message>
        <location line="-4"/>
        <source>Pitch angle, in degrees (Euler angles in the device&apos;s convention, ENU 312 by default).</source>
        <translation>俯仰角，單位 °（裝置約定的歐拉角，預設 ENU 312 順序）。</translation>
    </message>
    <message>
        <location line="-82"/>
        <source>Heading</source>
        <translation>航向</translation>
    </message>
    <message>
        <location line="+84"/>
        <source>Yaw (heading) angle, in degrees (Euler angles in the device&apos;s convention, ENU 312 by default).</source>
        <translation>航向角，單位 °（裝置約定的歐拉角，預設 ENU 312 順序）。</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Attitude quaternion, component %1 (body to the North-West-Up frame the module is set to), no unit.</source>
        <translation>姿態四元數的 %1 分量（載體系到模組所設的北西天座標系），無單位。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Attitude quaternion, component %1 (body to navigation frame), no unit.</source>
        <translation>姿態四元數的 %1 分量（載體座標系到導航座標系），無單位。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Air pressure from the barometer, in Pa.</source>
        <translation>氣壓計測得的氣壓，單位 Pa。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Sensor temperature, in °C.</source>
        <translation>感測器溫度，單位 °C。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Device timestamp: the UTC time of day once a PPS input has aligned the module&apos;s clock (HI91, UTC_UNSYNC clear), otherwise ms since power-up.</source>
        <translation>裝置時間戳：PPS 輸入將模組時鐘對齊後為當日 UTC 時間（HI91，UTC_UNSYNC 清除），否則為上電以來的毫秒數。</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>Heading from the latest NMEA heading sentence, in degrees clockwise from north: HDT true north, HDM magnetic north (an HEC495 with output content NMEA 0183 sends HDT).</source>
        <translation>最新一條 NMEA 航向語句給出的航向，單位度，自北順時針：HDT 為真北，HDM 為磁北（輸出內容設為 NMEA 0183 的 HEC495 傳送 HDT）。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The compass&apos;s magnetic field along its X, Y and Z axes as a relative value without unit: the horizontal component of the field pointing north is 1 (HEC495 manual 2.5, the same on CAN).</source>
        <translation>羅盤沿 X、Y、Z 軸的磁場，為無因次的相對值：指向北的水平分量為 1（HEC495 手冊 2.5，CAN 上相同）。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Magnetic roll (magnetic tool face), in degrees: the roll from the magnetic field, meaningful when the pitch is near ±90° (HEC495 manual 2.5).</source>
        <translation>磁性橫滾（磁性工具面），單位為度：由磁場得到的橫滾角，俯仰接近 ±90° 時才有意義（HEC495 手冊 2.5）。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>UTC date from the HI83 frame (bit 6), shown once GNSS time is known.</source>
        <translation>HI83 幀中的 UTC 日期（位 6），獲得 GNSS 時間後顯示。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ship motion frequency (HI83 bit 11): heave, surge, sway, in Hz.</source>
        <translation>船舶運動頻率（HI83 位 11）：升沉、縱蕩、橫蕩，單位 Hz。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Acceleration in the east-north-up frame from integrated navigation (HI83 bit 13): E, N, U, in m/s².</source>
        <translation>組合導航輸出的東北天座標系加速度（HI83 位 13）：東、北、天，單位 m/s²。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Heading solution state of the GNSS (HI83 bit 15, solq_heading), then in brackets its satellites.</source>
        <translation>GNSS 航向解狀態（HI83 位 15，solq_heading），括號內為其使用的衛星數。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Speed from an external odometer (HI83 bit 16), in m/s.</source>
        <translation>外接里程計速度（HI83 位 16），單位 m/s。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Geoid undulation: height of the geoid above the ellipsoid (HI83 bit 17), in m.</source>
        <translation>高程異常：大地水準面相對橢球面的高度（HI83 位 17），單位 m。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Age of the RTK differential corrections (HI83 bit 18), in s.</source>
        <translation>RTK 差分齡期（HI83 位 18），單位 s。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The module&apos;s node ID, the same as its CAN ID, 1 to 127 (HI83 bit 19).</source>
        <translation>模組節點 ID，與 CAN ID 相同，1 至 127（HI83 位 19）。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Measurement updates the integrated navigation filter has made (HI83 bit 25), the counters that are not zero: grav gravity, mag magnetometer, pos GNSS position, vel GNSS velocity, dual dual-antenna heading, nhc non-holonomic constraint, zupt zero velocity, zaru zero angular rate, zihr zero heading change, od odometer; a number for the reserved counters 10 to 15.</source>
        <translation>組合導航濾波器已進行的量測更新次數（HI83 位 25），只列出非零計數：grav 重力、mag 磁力計、pos GNSS 位置、vel GNSS 速度、dual 雙天線航向、nhc 非完整約束、zupt 零速、zaru 零角速率、zihr 零航向變化、od 里程計；保留計數 10 至 15 以編號顯示。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Accelerometer bias the navigation filter estimates (HI83 bit 26): X, Y, Z, in m/s².</source>
        <translation>導航濾波器估計的加速度零偏（HI83 位 26）：X、Y、Z，單位 m/s²。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Gyroscope bias the navigation filter estimates (HI83 bit 27): X, Y, Z, in rad/s.</source>
        <translation>導航濾波器估計的陀螺零偏（HI83 位 27）：X、Y、Z，單位 rad/s。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>GNSS accuracy (HI83 bit 28): norm of the position standard deviation in m, of the velocity standard deviation in m/s.</source>
        <translation>GNSS 精度（HI83 位 28）：位置標準差範數，單位 m；速度標準差範數，單位 m/s。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Dual-antenna GNSS heading (HI83 bit 29): baseline length in m, pitch and heading in degrees.</source>
        <translation>雙天線 GNSS 航向（HI83 位 29）：基線長度，單位 m；俯仰角和航向角，單位度。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Raw GNSS position (HI83 bit 30): latitude and longitude in degrees, height above mean sea level in m.</source>
        <translation>GNSS 原始位置（HI83 位 30）：緯度和經度，單位度；海拔高度，單位 m。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Raw GNSS velocity (HI83 bit 31): east, north, up, in m/s.</source>
        <translation>GNSS 原始速度（HI83 位 31）：東、北、天，單位 m/s。</translation>
    </message>
    <message>
        <location line="-54"/>
        <source>Integrated navigation state: 0 invalid, 1 aligning, 3 navigating, 6 dead reckoning.</source>
        <translation>組合導航解狀態：0 解無效，1 對準中，3 組合導航中，6 慣性遞推中。</translation>
    </message>
    <message numerus="yes">
        <location line="-362"/>
        <source>No new value for %n s: the device stopped sending this quantity (another output content, a polled record that stopped, or a link that went quiet).</source>
        <translation>
            <numerusform>%n 秒內無新值：裝置已停止傳送此量（輸出內容已更改、輪詢記錄已停止，或連線已靜默）。</numerusform>
        </translation>
    </message>
    <message>
        <location line="+364"/>
        <source>Position from integrated navigation, in degrees (south and west negative).</source>
        <translation>組合導航解算的位置，單位 °（南緯和西經為負）。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Height above mean sea level, in m.</source>
        <translation>平均海平面以上的高度，單位 m。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Velocity in the east-north-up frame, in m/s.</source>
        <translation>東北天（ENU）座標系下的速度，單位 m/s。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>GNSS fix quality as in NMEA GGA, then in brackets the satellites used, from the latest GGA or SXT sentence.</source>
        <translation>GNSS 定位品質（與 NMEA GGA 相同），括號內為使用的衛星數，取自最新的 GGA 或 SXT 語句。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>UTC time of day from the latest NMEA sentence (GGA, RMC or SXT), hh:mm:ss.ss.</source>
        <translation>取自最新 NMEA 語句（GGA、RMC 或 SXT）的 UTC 當日時間，格式 hh:mm:ss.ss。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Ship motion displacement (heave, surge, sway), in m.</source>
        <translation>船舶運動位移（垂蕩、縱蕩、橫蕩），單位 m。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Inclinometer angle about the %1 axis, in degrees.</source>
        <translation>傾角儀繞 %1 軸的角度，單位 °。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>MAIN_STATUS flags set in the latest frame (firmware 1.7.0 and later), then the raw word in hex.</source>
        <translation>最新一幀中設定的 MAIN_STATUS 旗標（韌體 1.7.0 及以上），括號內為十六進位原始值。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The frame type (packet tag) that carried the latest values, e.g. HI91.</source>
        <translation>攜帶最新數值的幀類型（封包標籤），例如 HI91。</translation>
    </message>
</context>
<context>
    <name>imudesk::models::RegisterTableModel</name>
    <message>
        <location filename="../core/itemmodels/register_table_model.cpp" line="+146"/>
        <source>Address</source>
        <translation>位址</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Name</source>
        <translation>名稱</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Type</source>
        <translation>類型</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Access</source>
        <translation>存取</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Raw</source>
        <translation>原始值</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Value</source>
        <translation>數值</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Unit</source>
        <translation>單位</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Description</source>
        <translation>說明</translation>
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
        <translation>未知的設定「%1」</translation>
    </message>
    <message>
        <location line="+66"/>
        <source>Key: %1</source>
        <translation>鍵名：%1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Takes effect: %1</source>
        <translation>生效時機：%1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Read back by: %1</source>
        <translation>回讀方式：%1</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>read the device first</source>
        <translation>請先讀取裝置</translation>
    </message>
    <message>
        <location line="+42"/>
        <source>Setting</source>
        <translation>設定項</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Key</source>
        <translation>鍵名</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>On the device</source>
        <translation>裝置上</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>New value</source>
        <translation>新值</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Takes effect</source>
        <translation>生效時機</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Read back by</source>
        <translation>回讀方式</translation>
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
        <translation>磁場 %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Roll</source>
        <translation>橫滾角</translation>
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
        <translation>四元數 %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Air pressure</source>
        <translation>氣壓</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Temperature</source>
        <translation>溫度</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+1"/>
        <location line="+1"/>
        <source>Relative magnetic field %1</source>
        <translation>相對磁場 %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Magnetic roll</source>
        <translation>磁性橫滾</translation>
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
        <translation>%1：%2。將重播完好的部分。</translation>
    </message>
    <message numerus="yes">
        <location line="+3"/>
        <source>%n damaged chunk(s) skipped</source>
        <translation>
            <numerusform>已略過 %n 個損壞區塊</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>imudesk::results::ResultsStore</name>
    <message>
        <location filename="../core/results/results_store.cpp" line="+267"/>
        <source>Updating the results database %1 to schema %2 failed: %3</source>
        <translation>將結果資料庫 %1 升級到結構描述 %2 失敗：%3</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>Qt&apos;s PostgreSQL driver is not installed (on Debian: the package libqt6sql6-psql).</source>
        <translation>未安裝 Qt 的 PostgreSQL 驅動程式（Debian 上為套件 libqt6sql6-psql）。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Qt&apos;s SQLite driver is not installed (on Debian: the package libqt6sql6-sqlite).</source>
        <translation>未安裝 Qt 的 SQLite 驅動程式（Debian 上為套件 libqt6sql6-sqlite）。</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>Cannot open the results database %1: %2</source>
        <translation>無法開啟結果資料庫 %1：%2</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>%1 was written by a newer ImuDesk (schema %2; this one knows %3): update ImuDesk to use it</source>
        <translation>%1 由較新版本的 ImuDesk 寫入（結構描述 %2；本版本支援 %3）：請更新 ImuDesk 後再使用</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The results database %1 has schema %2, this ImuDesk needs %3: have its owner run &quot;imudesk-cli results setup&quot; on it.</source>
        <translation>結果資料庫 %1 的結構描述為 %2，本 ImuDesk 需要 %3：請讓其擁有者對它執行「imudesk-cli results setup」。</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>the results database is not open</source>
        <translation>結果資料庫未開啟</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Storing the result of %1 in %2 failed: %3. It is still in the run folder.</source>
        <translation>將 %1 的結果存入 %2 失敗：%3。結果仍保存在執行資料夾中。</translation>
    </message>
    <message>
        <location line="+46"/>
        <source>Storing results in %1 failed: %2. They are still in the run folder.</source>
        <translation>將結果存入 %1 失敗：%2。結果仍保存在執行資料夾中。</translation>
    </message>
    <message>
        <location line="+320"/>
        <source>Roles are a PostgreSQL server&apos;s; %1 is an SQLite file.</source>
        <translation>角色屬於 PostgreSQL 伺服器；%1 是 SQLite 檔案。</translation>
    </message>
</context>
<context>
    <name>imudesk::results::ResultsUploader</name>
    <message>
        <location filename="../core/results/results_uploader.cpp" line="+28"/>
        <source>%1 is gone from the station; its record keeps the station&apos;s path</source>
        <translation>%1 已不在測試站上；其記錄保留測試站上的路徑</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Cannot create %1 in the shared artifact folder: check that it is mounted and writable.</source>
        <translation>無法在共用附件資料夾中建立 %1：請檢查它已掛載且可寫入。</translation>
    </message>
    <message>
        <location line="+5"/>
        <location line="+10"/>
        <source>Cannot copy %1 to %2: check that the shared folder is mounted and has room.</source>
        <translation>無法將 %1 複製到 %2：請檢查共用資料夾已掛載且有足夠空間。</translation>
    </message>
    <message>
        <location line="-5"/>
        <source>The copy of %1 in the shared folder does not match its SHA-256; it will be copied again.</source>
        <translation>共用資料夾中 %1 的副本與其 SHA-256 不符；將重新複製。</translation>
    </message>
</context>
<context>
    <name>imudesk::settings::ConfigurationController</name>
    <message>
        <location filename="../core/settings/configuration_controller.cpp" line="+24"/>
        <source>verified</source>
        <translation>已驗證</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not taken (read back differs)</source>
        <translation>未生效（回讀值不符）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>refused (ERR)</source>
        <translation>被拒絕（ERR）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no reply</source>
        <translation>無回應</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not sent</source>
        <translation>未傳送</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>the device has not been read yet (its model and firmware decide which settings exist)</source>
        <translation>尚未讀取裝置（可用的設定取決於其型號和韌體）</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>unknown setting &apos;%1&apos; (settings: %2)</source>
        <translation>未知的設定「%1」（可用設定：%2）</translation>
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
        <translation>裝置未回報其型號和韌體（LOG VERSION：%1）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>incomplete reply</source>
        <translation>回應不完整</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>LOG COMCONFIG failed (%1): the settings shown may be out of date</source>
        <translation>LOG COMCONFIG 失敗（%1）：顯示的設定可能不是最新的</translation>
    </message>
    <message>
        <location line="+18"/>
        <location line="+13"/>
        <location line="+129"/>
        <source>another configuration step is still running</source>
        <translation>另一個配置步驟仍在執行中</translation>
    </message>
    <message>
        <location line="-75"/>
        <location line="+97"/>
        <source>the device answered %1</source>
        <translation>裝置回應 %1</translation>
    </message>
    <message>
        <location line="-79"/>
        <source>an empty reply</source>
        <translation>空回應</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>the module did not answer the read-back (%1); check it with LOG COMCONFIG</source>
        <translation>模組未回應讀回（%1）；請用 LOG COMCONFIG 檢查</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>LOG COMCONFIG did not report %1 in a form ImuDesk reads; the reply was: %2</source>
        <translation>LOG COMCONFIG 未以 ImuDesk 能讀取的形式回報 %1；回應為：%2</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the device reports %1</source>
        <translation>裝置回報 %1</translation>
    </message>
    <message>
        <location line="-267"/>
        <source>could not be read back</source>
        <translation>無法回讀</translation>
    </message>
    <message>
        <location line="+298"/>
        <source>unknown action &apos;%1&apos;</source>
        <translation>未知的操作「%1」</translation>
    </message>
</context>
<context>
    <name>imudesk::settings::ProfileBatch</name>
    <message>
        <location filename="../core/settings/profile_batch.cpp" line="+50"/>
        <source>cannot connect: %1</source>
        <translation>無法連線：%1</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>SAVECONFIG failed: %1</source>
        <translation>SAVECONFIG 失敗：%1</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>%1=%2 not applied: %3</source>
        <translation>%1=%2 未套用：%3</translation>
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
        <translation>無法建立 CAN 裝置 %1:%2：%3</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>cannot open CAN device %1:%2: %3</source>
        <translation>無法開啟 CAN 裝置 %1:%2：%3</translation>
    </message>
    <message>
        <location line="+100"/>
        <source>--can needs PLUGIN:INTERFACE, e.g. virtualcan:can0</source>
        <translation>--can 需要 PLUGIN:INTERFACE 格式，例如 virtualcan:can0</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>--protocol must be j1939 or canopen</source>
        <translation>--protocol 必須為 j1939 或 canopen</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>--device must be hipnuc or hec495</source>
        <translation>--device 必須為 hipnuc 或 hec495</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>--node must be 1..127</source>
        <translation>--node 必須在 1..127 之間</translation>
    </message>
</context>
<context>
    <name>imudesk::sim::SimulatedTransport</name>
    <message>
        <location filename="../core/sim/simulated_transport.cpp" line="+86"/>
        <source>The connection to %1 was lost (simulated unplug). Check the cable; everything received so far is kept.</source>
        <translation>與 %1 的連線已中斷（模擬拔除）。請檢查線纜；已收到的資料全部保留。</translation>
    </message>
</context>
<context>
    <name>imudesk::station::ModuleRunner</name>
    <message>
        <location filename="../core/station/module_runner.cpp" line="+85"/>
        <source>the module did not answer on %1 within %2 s: check the cable, the power and the port</source>
        <translation>模組在 %2 s 內未在 %1 上應答：請檢查線纜、電源和串列埠</translation>
    </message>
    <message>
        <location line="+40"/>
        <source>the module&apos;s settings could not be read: %1</source>
        <translation>無法讀取模組的設定：%1</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>updated from %1 to %2 and verified</source>
        <translation>已從 %1 升級到 %2 並校驗通過</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>after the update the module reports firmware %1, older than %2</source>
        <translation>升級後模組報告的韌體為 %1，低於 %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+234"/>
        <location line="+1"/>
        <source>(none)</source>
        <translation>（無）</translation>
    </message>
    <message>
        <location line="-217"/>
        <source>could not connect to %1: %2</source>
        <translation>無法連線到 %1：%2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the module disappeared during &quot;%1&quot; (%2): check its cable; the other modules go on</source>
        <translation>模組在“%1”期間斷開（%2）：請檢查其線纜；其他模組繼續測試</translation>
    </message>
    <message>
        <location line="+89"/>
        <source>%1; marginal: %2</source>
        <translation>%1；臨界：%2</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>not run: &quot;%1&quot; failed</source>
        <translation>未執行：“%1”失敗</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>disabled in the plan</source>
        <translation>計畫中已停用</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>cancelled by the operator</source>
        <translation>已由操作員取消</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>%1 (marginal &gt; %2)</source>
        <translation>%1（臨界 &gt; %2）</translation>
    </message>
    <message>
        <location line="+39"/>
        <source>%1, firmware %2, serial %3</source>
        <translation>%1，韌體 %2，序列號 %3</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>(no product name)</source>
        <translation>（無產品型號）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1: not one of %2</source>
        <translation>%1：不屬於 %2</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1: firmware outside %2 … %3</source>
        <translation>%1：韌體不在 %2 … %3 範圍內</translation>
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
        <translation>測試計劃中的最低韌體“%1”不是有效的版本號</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>firmware %1 is at least %2: no update needed</source>
        <translation>韌體 %1 不低於 %2：無需升級</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>firmware %1 is older than %2 and the plan names no image to update from</source>
        <translation>韌體 %1 低於 %2，且測試計劃未指定用於升級的韌體映像</translation>
    </message>
    <message>
        <location line="+6"/>
        <location line="+5"/>
        <source>%1: %2 (nothing was sent to the module)</source>
        <translation>%1：%2（未向模組傳送任何資料）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>updating from %1 …</source>
        <translation>正在從 %1 升級…</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>the update failed: %1</source>
        <translation>升級失敗：%1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>the module did not come back after the update within %1 s</source>
        <translation>升級後模組未在 %1 s 內恢復連線</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the updater could not start</source>
        <translation>無法啟動升級程式</translation>
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
        <translation>模組無法接受：%1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the module already holds every setting of the profile</source>
        <translation>模組已具有配置方案中的全部設定</translation>
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
            <numerusform>已應用並回讀 %n 項設定</numerusform>
        </translation>
    </message>
    <message>
        <location line="+14"/>
        <source>SAVECONFIG answered OK</source>
        <translation>SAVECONFIG 已應答 OK</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>SAVECONFIG failed: %1</source>
        <translation>SAVECONFIG 失敗：%1</translation>
    </message>
    <message>
        <location line="+43"/>
        <source>no data from the module for %1 s during &quot;%2&quot;: is its output on, is it still connected?</source>
        <translation>“%2”期間 %1 s 未收到模組資料：模組輸出是否已開啟？是否仍在連線中？</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>only %1 samples in %2 s: enable the module&apos;s output (HI91, at least 10 Hz)</source>
        <translation>%2 s 內僅有 %1 個樣本：請開啟模組的輸出（HI91，至少 10 Hz）</translation>
    </message>
    <message>
        <location line="+39"/>
        <source>cannot judge: %1 (%2). Keep the module still on the fixture and test it again.</source>
        <translation>無法判定：%1（%2）。請讓模組在治具上保持靜止後重新測試。</translation>
    </message>
    <message>
        <location line="+40"/>
        <source>%1 samples within every limit</source>
        <translation>%1 個樣本，均在限值內</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1 samples; values outside the limits are marked</source>
        <translation>%1 個樣本；超出限值的數值已標出</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>%1 s of data do not reach τ = %2 s: measure for at least %3 s</source>
        <translation>%1 s 的資料不足以達到 τ = %2 s：請至少測量 %3 s</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>σ(%1 s) of each gyro axis</source>
        <translation>陀螺儀各軸的 σ(%1 s)</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>the module&apos;s output carries no Euler angles: enable HI91 in the profile</source>
        <translation>模組輸出中沒有尤拉角：請在配置方案中啟用 HI91</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>mounted as expected</source>
        <translation>安裝方向符合預期</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>roll %1°, pitch %2°: the module is not mounted as the plan expects</source>
        <translation>橫滾角 %1°，俯仰角 %2°：模組的安裝方向與測試計劃不符</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>the module reported no firmware version, so the calibration commands are unknown</source>
        <translation>模組未報告韌體版本，因此無法確定校準指令</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>the calibration did not end within %1 s</source>
        <translation>校準未在 %1 s 內結束</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>the turns did not end within %1 s: is the module on the turntable?</source>
        <translation>轉動未在 %1 s 內結束：模組是否已放在轉檯上？</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>no run folder to record into</source>
        <translation>沒有可供記錄的執行資料夾</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>the recording stopped: %1</source>
        <translation>記錄已停止：%1</translation>
    </message>
    <message>
        <location filename="../core/station/module_runner_verify.cpp" line="+42"/>
        <source>cannot judge: %1</source>
        <translation>無法判定：%1</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>%1 poses; %2</source>
        <translation>%1 個姿態；%2</translation>
    </message>
</context>
<context>
    <name>imudesk::station::RunFolder</name>
    <message>
        <location filename="../core/station/run_folder.cpp" line="+35"/>
        <source>cannot write %1: %2. Free some space or choose another report folder.</source>
        <translation>無法寫入 %1：%2。請釋放一些空間或選擇其他報告資料夾。</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>cannot create the report folder %1: choose a folder you may write to</source>
        <translation>無法建立報告資料夾 %1：請選擇有寫入許可權的資料夾</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1 holds a run of another plan; choose a new folder so that results stay comparable</source>
        <translation>%1 中已有其他測試計劃的執行結果；請選擇新資料夾，以保證結果可比</translation>
    </message>
    <message>
        <location line="+99"/>
        <source>Cannot write %1: %2. The result is in the results database and the summaries.</source>
        <translation>無法寫入 %1：%2。結果已保存在結果資料庫與摘要檔中。</translation>
    </message>
</context>
<context>
    <name>imudesk::station::StationSession</name>
    <message>
        <location filename="../core/station/station_session.cpp" line="+81"/>
        <source>The plan %1 could not be opened: %2</source>
        <translation>無法開啟測試計劃 %1：%2</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Wait for the run to end, or cancel it, before changing the simulated tray.</source>
        <translation>請等待執行結束或將其取消，然後再更改模擬托盤。</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>a good module</source>
        <translation>正常模組</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>a noisy gyro (%1 times the noise)</source>
        <translation>陀螺儀噪聲過大（噪聲為正常的 %1 倍）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>mounted wrongly (on its side, roll %1°)</source>
        <translation>安裝方向錯誤（側放，橫滾 %1°）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>old firmware</source>
        <translation>舊版韌體</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>The simulated modules could not start: %1</source>
        <translation>模擬模組無法啟動：%1</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Simulated HI14 %1 of %2, firmware %3: %4</source>
        <translation>模擬 HI14（第 %1 個，共 %2 個），韌體 %3：%4</translation>
    </message>
    <message>
        <location line="+74"/>
        <source>Open a test plan first (Open…), or start from the example.</source>
        <translation>請先開啟測試計劃（“開啟…”），或從示例新建。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The plan &quot;%1&quot; cannot run:
• %2
Edit it (Edit…) and start again.</source>
        <translation>測試計劃“%1”無法執行：
• %2
請編輯該計劃（“編輯…”）後重新開始。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Check the ports of the modules to test first.</source>
        <translation>請先勾選待測模組的串列埠。</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>The report folder cannot be used: %1</source>
        <translation>報告資料夾無法使用：%1</translation>
    </message>
    <message>
        <location line="+72"/>
        <source>No run yet.</source>
        <translation>尚未執行。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 passed · %2 failed · %3 running · %4 waiting</source>
        <translation>%1 通過 · %2 失敗 · %3 執行中 · %4 等待</translation>
    </message>
    <message>
        <location line="+12"/>
        <source> — the workspace of %1 opens when its test has ended</source>
        <translation> — %1 的工作區將在其測試結束後開啟</translation>
    </message>
    <message>
        <location line="+1"/>
        <source> — the workspaces of %1 open when their tests have ended</source>
        <translation> — %1 的工作區將在各自測試結束後開啟</translation>
    </message>
</context>
<context>
    <name>imudesk::station::TestPlan</name>
    <message>
        <location filename="../core/station/test_plan.cpp" line="+99"/>
        <source>Identify</source>
        <translation>識別</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Firmware version</source>
        <translation>韌體版本</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Apply profile</source>
        <translation>應用配置方案</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Static noise and bias</source>
        <translation>靜態噪聲和零偏</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Allan deviation</source>
        <translation>阿倫方差</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Attitude (mounting)</source>
        <translation>姿態（安裝方向）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Magnetometer calibration</source>
        <translation>地磁校準</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Gyro scale factor</source>
        <translation>陀螺儀標度因數</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Verify module</source>
        <translation>驗證模組</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save configuration</source>
        <translation>儲存配置</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Record evidence</source>
        <translation>證據記錄</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>The module reports an expected product and a firmware version within the range.</source>
        <translation>模組報告的產品型號符合預期，韌體版本在範圍內。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Firmware older than the minimum is updated from the image and verified; newer passes as it is.</source>
        <translation>低於最低版本的韌體將用韌體映像升級並校驗；不低於該版本的直接通過。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The profile&apos;s settings are applied and every one is read back.</source>
        <translation>應用配置方案中的設定，並逐項回讀。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>At rest: per-axis standard deviation and mean of the gyro, accelerometer noise and the gravity magnitude against their limits.</source>
        <translation>靜止狀態下：將陀螺儀各軸的標準差和均值、加速度計噪聲以及重力幅值與各自的限值比較。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The gyro&apos;s Allan deviation at the averaging time, worst axis, below the limit.</source>
        <translation>陀螺儀在該平均時間下的阿倫方差（取最差軸）低於限值。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Roll and pitch at rest within the tolerance of the expected orientation: the module is mounted as intended.</source>
        <translation>靜止時橫滾角和俯仰角與預期姿態的偏差在容差內：模組按預期方向安裝。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The module&apos;s own magnetometer calibration (MCAL) runs to the end and succeeds; the module must be turned through every attitude meanwhile (a rotation fixture).</source>
        <translation>模組自身的地磁校準（MCAL）執行完畢併成功；期間必須將模組轉過所有姿態（使用旋轉工裝）。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>On a turntable: two turns each way; the gyro&apos;s scale-factor error below the limit.</source>
        <translation>在轉檯上：正反方向各轉兩圈；陀螺儀標度因數誤差低於限值。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Turned through at least 9 still poses (by hand or a fixture): the accelerometer&apos;s bias and scale, the gyro&apos;s bias and scale and the attitude&apos;s tilt and heading, each within its limit.</source>
        <translation>依次轉到至少 9 個靜止姿態（手持或用治具）：加速度計的零偏和標度、陀螺儀的零偏和標度以及姿態的傾角和航向，各自在限值之內。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>SAVECONFIG: the module keeps its settings after a restart.</source>
        <translation>SAVECONFIG：模組重啟後保留其設定。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The module&apos;s output is recorded into the run folder as evidence.</source>
        <translation>將模組的輸出記錄到執行資料夾中作為證據。</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Products</source>
        <translation>產品型號</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Product names the module may report, separated by commas (HI14 matches HI14R3)</source>
        <translation>模組可報告的產品型號，以逗號分隔（HI14 可匹配 HI14R3）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Lowest firmware</source>
        <translation>最低韌體版本</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Oldest firmware accepted, e.g. 1.6.6; empty: any</source>
        <translation>可接受的最低韌體版本，例如 1.6.6；留空：不限</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Highest firmware</source>
        <translation>最高韌體版本</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Newest firmware accepted; empty: any</source>
        <translation>可接受的最高韌體版本；留空：不限</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>At least</source>
        <translation>最低版本</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Modules with older firmware are updated</source>
        <translation>韌體低於此版本的模組將被升級</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Image</source>
        <translation>韌體映像</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Intel HEX or binary image, relative to the plan&apos;s folder; without one an older module fails this step</source>
        <translation>Intel HEX 或二進位制映像，路徑相對於測試計劃所在資料夾；未指定時，韌體較舊的模組在此步驟失敗</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Profile</source>
        <translation>配置方案</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Configuration profile (.json, saved from the profile dialog), relative to the plan&apos;s folder</source>
        <translation>配置方案（.json，從配置方案對話方塊儲存），路徑相對於測試計劃所在資料夾</translation>
    </message>
    <message>
        <location line="+6"/>
        <location line="+20"/>
        <location line="+21"/>
        <location line="+17"/>
        <location line="+28"/>
        <source>Duration</source>
        <translation>時長</translation>
    </message>
    <message>
        <location line="-85"/>
        <source>How long the module is measured at rest</source>
        <translation>模組靜止測量的時長</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Gyro noise max</source>
        <translation>陀螺儀噪聲上限</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Largest standard deviation of each gyro axis</source>
        <translation>陀螺儀各軸標準差的最大允許值</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+66"/>
        <source>Gyro bias max</source>
        <translation>陀螺儀零偏上限</translation>
    </message>
    <message>
        <location line="-65"/>
        <source>Largest magnitude of each gyro axis&apos;s mean at rest</source>
        <translation>靜止時陀螺儀各軸均值絕對值的最大允許值</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Accelerometer noise max</source>
        <translation>加速度計噪聲上限</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Largest standard deviation of each accelerometer axis</source>
        <translation>加速度計各軸標準差的最大允許值</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Gravity tolerance</source>
        <translation>重力容差</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The mean acceleration&apos;s magnitude may differ from 1 G by this much</source>
        <translation>平均加速度的幅值與 1 G 之差允許的最大值</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>How long the module is measured at rest (at least 10 averaging times)</source>
        <translation>模組靜止測量的時長（至少為平均時間的 10 倍）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Averaging time</source>
        <translation>平均時間</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>τ at which the Allan deviation is read</source>
        <translation>讀取阿倫方差所用的 τ</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>σ(τ) max</source>
        <translation>σ(τ) 上限</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Largest Allan deviation of any gyro axis at τ</source>
        <translation>陀螺儀任一軸在 τ 處阿倫方差的最大允許值</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Expected roll</source>
        <translation>預期橫滾角</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Roll of the module in its fixture (Z up: 0)</source>
        <translation>模組在工裝中的橫滾角（Z 軸朝上：0）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Expected pitch</source>
        <translation>預期俯仰角</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Pitch of the module in its fixture (Z up: 0)</source>
        <translation>模組在工裝中的俯仰角（Z 軸朝上：0）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Tolerance</source>
        <translation>容差</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Largest difference of roll and of pitch</source>
        <translation>橫滾角和俯仰角各自允許的最大偏差</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The angles are averaged over this time</source>
        <translation>在此時長內對角度取平均</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+8"/>
        <source>Time limit</source>
        <translation>時間限值</translation>
    </message>
    <message>
        <location line="-7"/>
        <source>The calibration fails when it has not ended by then</source>
        <translation>到時仍未結束則校準失敗</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Scale error max</source>
        <translation>標度因數誤差上限</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Largest scale-factor error of the Z gyro</source>
        <translation>Z 軸陀螺儀標度因數誤差的最大允許值</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The run fails when the turns have not ended by then</source>
        <translation>到時轉動仍未結束則本次測試失敗</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>How long the module is turned through its poses (3 s still in each, at least 9)</source>
        <translation>模組依次轉過各姿態的時長（每個姿態靜止 3 s，至少 9 個）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Local gravity</source>
        <translation>當地重力</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The station&apos;s gravity (m/s²); 0: standard gravity assumed, with its uncertainty</source>
        <translation>工作站的重力（m/s²）；0：假定為標準重力，並計入其不確定度</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Accelerometer bias max</source>
        <translation>加速度計零偏上限</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Largest accelerometer bias of any axis</source>
        <translation>任一軸加速度計零偏的最大值</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Accelerometer scale error max</source>
        <translation>加速度計標度誤差上限</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Largest accelerometer scale error of any axis</source>
        <translation>任一軸加速度計標度誤差的最大值</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Largest gyro bias of any axis</source>
        <translation>任一軸陀螺儀零偏的最大值</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Gyro scale error max</source>
        <translation>陀螺儀標度誤差上限</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Largest gyro scale error of any axis</source>
        <translation>任一軸陀螺儀標度誤差的最大值</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Tilt error max</source>
        <translation>傾角誤差上限</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Largest roll or pitch error of the module&apos;s attitude</source>
        <translation>模組姿態橫滾或俯仰誤差的最大值</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Heading error max</source>
        <translation>航向誤差上限</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Largest heading error of the module&apos;s attitude (needs a magnetometer)</source>
        <translation>模組姿態航向誤差的最大值（需要磁力計）</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>How long the module&apos;s output is recorded</source>
        <translation>記錄模組輸出的時長</translation>
    </message>
    <message>
        <location line="+64"/>
        <location line="+26"/>
        <source>%1 has no parameter &quot;%2&quot;</source>
        <translation>%1 沒有參數“%2”</translation>
    </message>
    <message>
        <location line="-23"/>
        <source>&quot;%1&quot; must be a text</source>
        <translation>“%1”必須是文字</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&quot;%1&quot; must be a firmware version such as 1.7.1, not &quot;%2&quot;</source>
        <translation>“%1”必須是韌體版本號（如 1.7.1），而不是“%2”</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&quot;%1&quot; must be a number</source>
        <translation>“%1”必須是數字</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&quot;%1&quot; = %2 is outside %3 … %4 %5</source>
        <translation>“%1” = %2 超出 %3 … %4 %5</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>&quot;%1&quot; is not a limit: it has no marginal band</source>
        <translation>“%1”不是限值：沒有臨界區間</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&quot;%1&quot;: &quot;marginal_high&quot; must be a number</source>
        <translation>“%1”：“marginal_high”必須是數字</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&quot;%1&quot;: &quot;marginal_high&quot; = %2 is outside %3 … %4%5</source>
        <translation>“%1”：“marginal_high” = %2 超出 %3 … %4%5</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>&quot;%1&quot;: &quot;marginal_high&quot; = %2%4 is not below the limit %3%4</source>
        <translation>“%1”：“marginal_high” = %2%4 不低於限值 %3%4</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>This plan was written in format version %1; it is converted to version %2 and will be saved as version %2.</source>
        <translation>此測試計劃以格式版本 %1 撰寫；已轉換為版本 %2，並將以版本 %2 儲存。</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>the plan is larger than %1 KiB</source>
        <translation>測試計劃大於 %1 KiB</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>not JSON: %1 at byte %2</source>
        <translation>不是 JSON：第 %2 位元組處：%1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>not a station plan (&quot;format&quot; is not &quot;%1&quot;)</source>
        <translation>不是生產測試臺的測試計劃（&quot;format&quot; 不是 &quot;%1&quot;）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>plan version %1 is not supported (this ImuDesk reads versions 1 to %2)</source>
        <translation>不支援測試計劃版本 %1（本 ImuDesk 讀取版本 1 至 %2）</translation>
    </message>
    <message>
        <location line="+8"/>
        <location line="+118"/>
        <source>the plan has no steps</source>
        <translation>測試計劃中沒有步驟</translation>
    </message>
    <message>
        <location line="-112"/>
        <source>step %1: unknown step &quot;%2&quot;</source>
        <translation>步驟 %1：未知步驟“%2”</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>step %1 (%2): &quot;enabled&quot; must be true or false</source>
        <translation>步驟 %1（%2）：&quot;enabled&quot; 必須為 true 或 false</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>step %1 (%2): &quot;%3&quot; has an unknown field &quot;%4&quot; (a limit is a number or {&quot;high&quot;: …, &quot;marginal_high&quot;: …})</source>
        <translation>步驟 %1（%2）：“%3”含有未知欄位“%4”（限值應為數字或 {&quot;high&quot;: …, &quot;marginal_high&quot;: …}）</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>step %1 (%2): &quot;%3&quot; has no &quot;high&quot; (the limit itself)</source>
        <translation>步驟 %1（%2）：“%3”缺少“high”（限值本身）</translation>
    </message>
    <message>
        <location line="+9"/>
        <location line="+3"/>
        <location line="+80"/>
        <location line="+4"/>
        <source>step %1 (%2): %3</source>
        <translation>步驟 %1（%2）：%3</translation>
    </message>
    <message>
        <location line="-42"/>
        <source>cannot open %1: %2</source>
        <translation>無法開啟 %1：%2</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>cannot write %1: %2. Choose another folder or free some space.</source>
        <translation>無法寫入 %1：%2。請選擇其他資料夾或釋放一些空間。</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>step %1 (%2): no %3 file given</source>
        <translation>步驟 %1（%2）：未指定 %3 檔案</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>step %1 (%2): %3 not found</source>
        <translation>步驟 %1（%2）：找不到 %3</translation>
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
        <translation>執行中</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>pass</source>
        <translation>通過</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>fail</source>
        <translation>失敗</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>skipped</source>
        <translation>已跳過</translation>
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
        <translation>單位</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Mean</source>
        <translation>平均值</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Std. dev.</source>
        <translation>標準差</translation>
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
        <translation>幀間隔（裝置時鐘）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Allan deviation</source>
        <translation>艾倫變異</translation>
    </message>
    <message>
        <location line="+53"/>
        <source>Analysing %1…</source>
        <translation>正在分析 %1…</translation>
    </message>
    <message>
        <location line="+42"/>
        <source>%1: %2 frames over %3 s, output rate %4 Hz, interval %5 ± %6 ms, frames lost %7</source>
        <translation>%1：%3 s 內共 %2 幀，輸出速率 %4 Hz，間隔 %5 ± %6 ms，遺失 %7 幀</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Allan deviation: %1 (%2)</source>
        <translation>阿倫方差：%1（%2）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Allan deviation σ(τ): deg/s for gyro, G for acc</source>
        <translation>阿倫方差 σ(τ)：陀螺儀為 deg/s，加速度計為 G</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Allan deviation: %1</source>
        <translation>阿倫方差：%1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>no noise to measure: its values never change (below the file&apos;s resolution, or a constant column)</source>
        <translation>無雜訊可測：數值從不變化（低於檔案的解析度，或為常數欄）</translation>
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
        <translation>零偏不穩定性 %1 deg/h（τ = %2 s）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>bias instability %1 mG at τ = %2 s</source>
        <translation>零偏不穩定性 %1 mG（τ = %2 s）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Recommended minimum recording length for τ up to %1 s: %2 h</source>
        <translation>τ 最大至 %1 s 時，建議的最短記錄時長：%2 h</translation>
    </message>
    <message>
        <location line="+14"/>
        <location line="+33"/>
        <source>frames</source>
        <translation>幀數</translation>
    </message>
    <message numerus="yes">
        <location line="-15"/>
        <source>%1 to %2 ms: %n frame(s)</source>
        <translation>
            <numerusform>%1 至 %2 ms：%n 幀</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+3"/>
        <source>%1 ms or more: %n frame(s)</source>
        <translation>
            <numerusform>%1 ms 以上：%n 幀</numerusform>
        </translation>
    </message>
    <message>
        <location line="+37"/>
        <source>interval, ms</source>
        <translation>間隔，ms</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>interval, ms (the last bar: %1 ms or more)</source>
        <translation>間隔，ms（最後一柱：%1 ms 及以上）</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>τ, s</source>
        <translation>τ, s</translation>
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
        <translation>航向角重設：目前航向角歸零。請保持模組靜止。（韌體 1.7.1 及以上版本。）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Relative zero: the current pitch and roll become 0, whatever they are. Keep the module still in the pose that should read level. CONFIG ATT RST 5 undoes it.</source>
        <translation>相對歸零：無論目前的俯仰角和橫滾角為何，都設為 0。請讓模組靜止在應視為水平的姿態。CONFIG ATT RST 5 可撤銷。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Auto level: only when the module lies nearly level (pitch and roll within 5 deg), or upside down (roll within 5 deg of 180): it is levelled to 0/0 or 0/180. Permanent: RST 5 does not undo it. Keep the module still.</source>
        <translation>自動調平：僅在模組接近水平（俯仰角和橫滾角在 5 deg 以內）或倒置（橫滾角與 180 相差 5 deg 以內）時有效：調平到 0/0 或 0/180。永久生效：RST 5 無法撤銷。請保持模組靜止。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Cancel levelling: clears the relative pitch and roll set by RST 2; the absolute angles come back.</source>
        <translation>取消調平：清除 RST 2 設定的相對俯仰角和橫滾角，恢復絕對角度。</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Attitude reset and level</source>
        <translation>姿態重設與調平</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>What to reset</source>
        <translation>重設項目</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Heading reset (ATT RST 1)</source>
        <translation>航向角重設（ATT RST 1）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Relative zero of pitch and roll (ATT RST 2)</source>
        <translation>俯仰角與橫滾角相對歸零（ATT RST 2）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Auto level (ATT RST 3)</source>
        <translation>自動調平（ATT RST 3）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cancel levelling (ATT RST 5)</source>
        <translation>取消調平（ATT RST 5）</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Hold the module still</source>
        <translation>保持模組靜止</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Send</source>
        <translation>傳送</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Result</source>
        <translation>結果</translation>
    </message>
    <message>
        <location line="+66"/>
        <source>not still yet (%1 of %2 s)</source>
        <translation>尚未靜止（%1/%2 s）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>not level: pitch %1, roll %2 deg (each must be within %3 deg of level or upside down)</source>
        <translation>未水平：俯仰角 %1，橫滾角 %2 deg（兩者與水平或倒置的偏差都必須在 %3 deg 以內）</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Roll %1, pitch %2, yaw %3 deg; gyro spread %4 deg/s.
%5</source>
        <translation>橫滾角 %1，俯仰角 %2，航向角 %3 deg；陀螺儀波動 %4 deg/s。
%5</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Ready: send CONFIG ATT RST %1.</source>
        <translation>就緒：傳送 CONFIG ATT RST %1。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Waiting: %1.</source>
        <translation>等待中：%1。</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>The device accepted CONFIG ATT RST %1 (OK).</source>
        <translation>裝置已接受 CONFIG ATT RST %1（OK）。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The device did not answer CONFIG ATT RST %1: its firmware may not know this variant.</source>
        <translation>裝置未回應 CONFIG ATT RST %1：其韌體可能不支援此選項。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The device refused CONFIG ATT RST %1 (ERR).</source>
        <translation>裝置拒絕 CONFIG ATT RST %1（ERR）。</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>Nothing was sent.</source>
        <translation>未傳送任何內容。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Attitude now: roll %1, pitch %2, yaw %3 deg. Save it with SAVECONFIG if it should survive a restart (RST 2).</source>
        <translation>目前姿態：橫滾角 %1，俯仰角 %2，航向角 %3 deg。若需在重新啟動後保留（RST 2），請以 SAVECONFIG 儲存。</translation>
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
        <translation>%2 s 內最大 %1°</translation>
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
        <translation>假定世界座標系為 %1：模組的 LOG COMCONFIG 回覆中沒有 COORD</translation>
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
        <translation>尚無姿態資料</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Roll</source>
        <translation>橫滾角</translation>
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
        <translation>拖曳以旋轉檢視，按兩下以重設</translation>
    </message>
    <message>
        <location line="+389"/>
        <source>Show ImuDesk&apos;s reference attitude</source>
        <translation>顯示 ImuDesk 的參考姿態</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>ImuDesk&apos;s own filter on the module&apos;s raw gyro and accelerometer, drawn as an outline: started from the module&apos;s heading when it last rested for 1 s</source>
        <translation>ImuDesk 以模組原始陀螺儀和加速度計資料自行解算的姿態，以輪廓線顯示：從模組上次靜止 1 s 時的航向開始</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Reset view</source>
        <translation>重設檢視</translation>
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
        <translation>HI83 欄位（MAP）：</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Message</source>
        <translation>訊息</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Rate</source>
        <translation>速率</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Bytes per frame</source>
        <translation>每幀位元組數</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Highest usual rate at this baud</source>
        <translation>此波特率下的常用最高速率</translation>
    </message>
    <message>
        <location line="+6"/>
        <source> Hz</source>
        <translation> Hz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>off</source>
        <translation>關閉</translation>
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
        <translation>%1 / %2 位元組/秒（佔鏈路的 %3 %）</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::BridgeController</name>
    <message>
        <location filename="../ui/bridge/bridge_controller.cpp" line="+87"/>
        <source>Live bridge %1</source>
        <translation>即時橋接 %1</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>clients: %1</source>
        <translation>用戶端：%1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>sent: %1</source>
        <translation>已傳送：%1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>dropped: %1</source>
        <translation>已捨棄：%1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Live bridge</source>
        <translation>即時橋接</translation>
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
        <translation>連線</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::CalibrationHistoryDialog</name>
    <message>
        <location filename="../ui/calibration/calibration_history_dialog.cpp" line="-199"/>
        <source>Calibration history</source>
        <translation>校準歷史</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Devices with calibration runs (by serial number)</source>
        <translation>有校準記錄的裝置（依序號）</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Before (raw samples)</source>
        <translation>校準前（原始樣本）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>After (corrected by this run)</source>
        <translation>校準後（經本輪校準校正）</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Export report (PDF)…</source>
        <translation>匯出報告（PDF）…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Export samples (CSV)…</source>
        <translation>匯出樣本（CSV）…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Open folder</source>
        <translation>開啟資料夾</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Delete</source>
        <translation>刪除</translation>
    </message>
    <message>
        <location line="+113"/>
        <source>No calibration runs yet. The calibration wizards keep every finished run here, in %1.</source>
        <translation>尚無校準記錄。校準精靈會將每次完成的校準保存在這裡，位於 %1。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Select a run.</source>
        <translation>請選擇一筆校準記錄。</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Verdict: %1</source>
        <translation>判定：%1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1, serial %2, firmware %3, %4 UTC, %5 samples</source>
        <translation>%1，序號 %2，韌體 %3，%4 UTC，%5 個樣本</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unknown product</source>
        <translation>未知產品</translation>
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
        <translation>無法讀取樣本：%1</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>Right: the same samples corrected by this run&apos;s hard and soft iron.</source>
        <translation>右：經本輪校準的硬鐵與軟鐵參數校正後的同一組樣本。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>This run has no usable correction: both spheres show the raw samples.</source>
        <translation>本輪校準沒有可用的校正參數：兩個球面皆顯示原始樣本。</translation>
    </message>
    <message>
        <location line="+16"/>
        <location line="+16"/>
        <location line="+21"/>
        <source>Select a run first.</source>
        <translation>請先選擇一筆校準記錄。</translation>
    </message>
    <message>
        <location line="-14"/>
        <source>Cannot write %1: %2. Choose another folder.</source>
        <translation>無法寫入 %1：%2。請選擇其他資料夾。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Cannot write %1: %2. Check the free disk space and try again.</source>
        <translation>無法寫入 %1：%2。請檢查可用磁碟空間後再試一次。</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Cannot delete %1: check the folder&apos;s permissions.</source>
        <translation>無法刪除 %1：請檢查資料夾權限。</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>Export calibration report</source>
        <translation>匯出校準報告</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PDF files (*.pdf)</source>
        <translation>PDF 檔案 (*.pdf)</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Export calibration samples</source>
        <translation>匯出校準樣本</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CSV files (*.csv)</source>
        <translation>CSV 檔案 (*.csv)</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Delete calibration run</source>
        <translation>刪除校準記錄</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Delete the %1 run of %2 and its samples? This cannot be undone.
%3</source>
        <translation>要刪除 %2 的 %1 校準記錄及其樣本嗎？此操作無法復原。
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
        <translation>套用</translation>
    </message>
    <message>
        <location line="-8"/>
        <source>SYNC mode (TPDO sent on each SYNC)</source>
        <translation>SYNC 模式（每次收到 SYNC 時傳送 TPDO）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Send SYNC</source>
        <translation>傳送 SYNC</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Output on</source>
        <translation>開啟輸出</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Output off</source>
        <translation>關閉輸出</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Save</source>
        <translation>儲存</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Reset</source>
        <translation>重設</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Factory defaults…</source>
        <translation>恢復出廠設定…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Scan nodes 1–127</source>
        <translation>掃描節點 1–127</translation>
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
        <translation>週期 SYNC 關閉</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Angles, acc., rate (0x02)</source>
        <translation>角度、加速度、角速度（0x02）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>HEC495 work mode, object 0x6245: 0x02 pitch, roll, acceleration and rate (default); 0x0A rate at 500 Hz</source>
        <translation>HEC495 工作模式，物件 0x6245：0x02 輸出俯仰、橫滾、加速度和角速度（預設）；0x0A 以 500 Hz 輸出角速度</translation>
    </message>
    <message>
        <location line="+219"/>
        <source>%1 kbit/s</source>
        <translation>%1 kbit/s</translation>
    </message>
    <message>
        <location line="-228"/>
        <source>Heading reset (J1939 1)</source>
        <translation>航向角重設（J1939 1）</translation>
    </message>
    <message>
        <location line="-18"/>
        <source>Trigger once</source>
        <translation>觸發一次</translation>
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
        <translation>所有節點開</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>All nodes off</source>
        <translation>所有節點關</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Set relative zero (2)</source>
        <translation>設定相對零點（2）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Auto level (J1939 3)</source>
        <translation>自動調平（J1939 3）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Clear zero (5)</source>
        <translation>清除零點（5）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>J1939 register 0x96: the module sends the chosen PGN once (no reply; the frame is the answer)</source>
        <translation>J1939 暫存器 0x96：模組傳送一次所選 PGN（無應答；資料幀即為回應）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Inclinometer X axis direction: J1939 register 0x9E, CANopen object 0x209E (0 default, 1 reversed)</source>
        <translation>傾角儀 X 軸正負方向：J1939 暫存器 0x9E，CANopen 物件 0x209E（0 預設，1 反向）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Inclinometer Y axis direction: J1939 register 0x9F, CANopen object 0x209F (0 default, 1 reversed)</source>
        <translation>傾角儀 Y 軸正負方向：J1939 暫存器 0x9F，CANopen 物件 0x209F（0 預設，1 反向）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Rate at 500 Hz (0x0A)</source>
        <translation>500 Hz 角速度（0x0A）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>HEC495 PDO mode, object 0x1080</source>
        <translation>HEC495 PDO 模式，物件 0x1080</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>NMT start to node 0: every node on the bus starts its PDOs (HEC495: not saved)</source>
        <translation>向節點 0 傳送 NMT 啟動：總線上所有節點開始傳送 PDO（HEC495：不儲存）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>NMT stop to node 0: every node on the bus stops its PDOs (HEC495: not saved)</source>
        <translation>向節點 0 傳送 NMT 停止：總線上所有節點停止傳送 PDO（HEC495：不儲存）</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Protocol:</source>
        <translation>協定：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Output period:</source>
        <translation>輸出週期：</translation>
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
        <translation>節點 ID：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CAN bit rate:</source>
        <translation>CAN 位元速率：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Attitude:</source>
        <translation>姿態：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Inclinometer:</source>
        <translation>傾角儀：</translation>
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
        <translation>輸出：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Every node:</source>
        <translation>所有節點：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Settings:</source>
        <translation>設定：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Discovery:</source>
        <translation>節點探索：</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Settings</source>
        <translation>設定</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Actions</source>
        <translation>操作</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>SYNC mode on</source>
        <translation>SYNC 模式開啟</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>SYNC mode off</source>
        <translation>SYNC 模式關閉</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>heartbeat</source>
        <translation>心跳</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>node ID %1</source>
        <translation>節點 ID %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>bit rate</source>
        <translation>位元速率</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>output on</source>
        <translation>開啟輸出</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>output off</source>
        <translation>關閉輸出</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>trigger %1 once</source>
        <translation>觸發一次 %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>inclinometer X reversed</source>
        <translation>傾角儀 X 反向</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>inclinometer X default</source>
        <translation>傾角儀 X 預設</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>inclinometer Y reversed</source>
        <translation>傾角儀 Y 反向</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>inclinometer Y default</source>
        <translation>傾角儀 Y 預設</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>every node on</source>
        <translation>所有節點開</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>every node off</source>
        <translation>所有節點關</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>save</source>
        <translation>儲存</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>reset</source>
        <translation>重設</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Factory defaults</source>
        <translation>恢復出廠設定</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Restore the module&apos;s default user settings? It saves and resets itself.</source>
        <translation>要恢復模組的預設使用者設定嗎？模組會自行儲存並重設。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>factory defaults</source>
        <translation>恢復出廠設定</translation>
    </message>
    <message>
        <location line="+46"/>
        <source>Scan cancelled; nodes answering so far: %1</source>
        <translation>掃描已取消；目前已回應的節點：%1</translation>
    </message>
    <message>
        <location line="+0"/>
        <location line="+1"/>
        <source>none</source>
        <translation>無</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Scan finished; nodes answering SDO: %1</source>
        <translation>掃描完成；回應 SDO 的節點：%1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Node %1 (%2, %3)</source>
        <translation>節點 %1（%2，%3）</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>no session</source>
        <translation>無連線</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>detecting…</source>
        <translation>偵測中…</translation>
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
        <translation>PDO 關閉</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>X message only (0)</source>
        <translation>僅 X 報文（0）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>X and Y messages (1)</source>
        <translation>X 和 Y 報文（1）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Float (0)</source>
        <translation>浮點（0）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Fixed point (1)</source>
        <translation>定點（1）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Float, 0x180/0x280 only (3)</source>
        <translation>浮點，僅 0x180/0x280（3）</translation>
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
        <translation>✓ %1：已確認（%2）</translation>
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
        <translation>透過 CAN 連線</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The Qt CAN plugin of the adapter: socketcan for Linux CAN interfaces, peakcan for PEAK adapters, virtualcan for a bus inside this computer</source>
        <translation>轉接器使用的 Qt CAN 外掛程式：socketcan 用於 Linux CAN 介面，peakcan 用於 PEAK 轉接器，virtualcan 用於本機內部的虛擬匯流排</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>P&amp;lugin:</source>
        <translation>外掛程式(&amp;L)：</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The interface of the plugin, e.g. can0</source>
        <translation>外掛程式的介面，例如 can0</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Interface:</source>
        <translation>介面(&amp;I)：</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Bit rate of the bus: the rates the chosen device&apos;s manual lists, its factory rate chosen first (HiPNUC 500 kbit/s, HEC495 250 kbit/s)</source>
        <translation>匯流排鮑率：所選裝置手冊列出的速率，預設選中其出廠速率（HiPNUC 500 kbit/s，HEC495 250 kbit/s）</translation>
    </message>
    <message>
        <location line="+81"/>
        <source>Keep the interface&apos;s setting</source>
        <translation>保留介面目前的設定</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 kbit/s (factory)</source>
        <translation>%1 kbit/s（出廠）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 kbit/s</source>
        <translation>%1 kbit/s</translation>
    </message>
    <message>
        <location line="-83"/>
        <source>&amp;Bit rate:</source>
        <translation>位元速率(&amp;B)：</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>CAN FD</source>
        <translation>CAN FD</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>A CAN FD bus: needed for the J1939 FF5A frame (64 bytes); the module must have CAN FD output enabled, which its manual gives no command for</source>
        <translation>CAN FD 匯流排：接收 J1939 FF5A 幀（64 位元組）所需；模組必須已啟用 CAN FD 輸出，手冊未給出相應命令</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 Mbit/s</source>
        <translation>%1 Mbit/s</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Bit rate of the CAN FD data phase (the manual: usually 4 Mbit/s)</source>
        <translation>CAN FD 資料段鮑率（手冊：通常為 4 Mbit/s）</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>&amp;Data phase:</source>
        <translation>資料段(&amp;D)：</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Detect from the traffic</source>
        <translation>依匯流排流量偵測</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>HEC495 compass</source>
        <translation>HEC495 羅盤</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>P&amp;rotocol:</source>
        <translation>協定(&amp;R)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Extended frames (0x18FA…)</source>
        <translation>擴展幀（0x18FA…）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The HEC495&apos;s extended-frame variant: requests on 0x18FA0227, replies on 0x18FA0216, data on 0x18FA0316 and 0x18FA0416 (its manual, &quot;CAN 扩展帧命令格式&quot;)</source>
        <translation>HEC495 的擴展幀方式：請求 0x18FA0227，應答 0x18FA0216，資料 0x18FA0316 和 0x18FA0416（其手冊“CAN 扩展帧命令格式”）</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>First that sends</source>
        <translation>第一個傳送的節點</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The node ID (CANopen) or source address (J1939) to follow</source>
        <translation>要追蹤的節點 ID（CANopen）或來源位址（J1939）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Node:</source>
        <translation>節點(&amp;N)：</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>1.7.x (node-ID object 0x209C)</source>
        <translation>1.7.x（節點 ID 物件 0x209C）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>1.6.6 (node-ID object 0x20A0)</source>
        <translation>1.6.6（節點 ID 物件 0x20A0）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>HiPNUC CANopen firmware: where it keeps its node ID</source>
        <translation>HiPNUC CANopen 韌體：節點 ID 的儲存位置</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Firmware:</source>
        <translation>韌體(&amp;F)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Start a simulated device on this bus</source>
        <translation>在此匯流排上啟動模擬裝置</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A simulated module of the chosen protocol answers on the bus (use the virtualcan plugin to try it without hardware)</source>
        <translation>由所選協定的模擬模組在匯流排上回應（使用 virtualcan 外掛程式，無需硬體即可試用）</translation>
    </message>
    <message>
        <location line="+47"/>
        <source>The module can be switched to %1 kbit/s (register 0x9A, after save and reset).</source>
        <translation>模組可切換到 %1 kbit/s（暫存器 0x9A，儲存並重設後生效）。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The module can be switched to %1 kbit/s (object 0x209A, after save and reset; no 800 kbit/s in CANopen).</source>
        <translation>模組可切換到 %1 kbit/s（物件 0x209A，儲存並重設後生效；CANopen 沒有 800 kbit/s）。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The compass can be switched to %1 kbit/s (object 0x1020, after a power cycle).</source>
        <translation>羅盤可切換到 %1 kbit/s（物件 0x1020，重新上電後生效）。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Choose the protocol to see the rates its devices use.</source>
        <translation>選擇協定以查看其裝置使用的速率。</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::CanMonitorWidget</name>
    <message>
        <location filename="../ui/bus/can_monitor_widget.cpp" line="+21"/>
        <source>Clear</source>
        <translation>清除</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Export CSV…</source>
        <translation>匯出 CSV…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Extended</source>
        <translation>擴充幀</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>FD</source>
        <translation>FD</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Send</source>
        <translation>傳送</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Filter: ID or meaning</source>
        <translation>篩選：ID 或含義</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Pause</source>
        <translation>暫停</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>ID (hex)</source>
        <translation>ID（十六進位）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>data (hex bytes)</source>
        <translation>資料（十六進位位元組）</translation>
    </message>
    <message>
        <location line="+43"/>
        <source>%1 frames, %2 IDs</source>
        <translation>%1 幀，%2 個 ID</translation>
    </message>
    <message>
        <location line="+2"/>
        <source> — paused (%1 frames not shown)</source>
        <translation> — 已暫停（%1 幀未顯示）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source> — %1 frames of IDs beyond the %2-row limit</source>
        <translation> — 超出 %2 列上限的 ID 共 %1 幀</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>The ID must be hexadecimal, 0 to 1FFFFFFF.</source>
        <translation>ID 必須為十六進位，範圍 0 至 1FFFFFFF。</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>The ID must be hexadecimal, 0 to 7FF (tick Extended for 29-bit IDs).</source>
        <translation>ID 必須為十六進位，範圍 0 至 7FF（29 位元 ID 請勾選「擴充幀」）。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The data must be pairs of hexadecimal digits, e.g. 2B 00 18 05 0A 00 00 00.</source>
        <translation>資料必須是成對的十六進位數字，例如 2B 00 18 05 0A 00 00 00。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>A CAN FD frame carries at most 64 bytes.</source>
        <translation>CAN FD 幀最多可承載 64 位元組。</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>A classic CAN frame carries at most 8 bytes (tick FD for more).</source>
        <translation>傳統 CAN 幀最多可承載 8 位元組（需要更多請勾選 FD）。</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Saved %1 IDs to %2</source>
        <translation>已將 %1 個 ID 儲存到 %2</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Export CAN frames</source>
        <translation>匯出 CAN 幀</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>CSV files (*.csv)</source>
        <translation>CSV 檔案 (*.csv)</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::CanSettingsTable</name>
    <message>
        <location filename="../ui/bus/can_settings_table.cpp" line="+57"/>
        <source>Setting</source>
        <translation>設定項</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>On the module</source>
        <translation>模組中的值</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>New value</source>
        <translation>新值</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Read back</source>
        <translation>讀回</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Read from module</source>
        <translation>從模組讀取(&amp;R)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Read every setting the module can report (J1939 register reads, CANopen SDO uploads)</source>
        <translation>讀取模組能報告的所有設定（J1939 暫存器讀取、CANopen SDO 上傳）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Write changed</source>
        <translation>寫入已更改項(&amp;W)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Write the new values you changed; each is read back and marked verified or not</source>
        <translation>寫入已更改的新值；每項都會讀回並標記是否已校驗</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The value on the module is read before anything is written; a write is read back.</source>
        <translation>寫入前先讀取模組中的值；寫入後會讀回校驗。</translation>
    </message>
    <message>
        <location line="+65"/>
        <source>not readable</source>
        <translation>無法讀取</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>%1; %2</source>
        <translation>%1；%2</translation>
    </message>
    <message>
        <location line="+85"/>
        <source>reading…</source>
        <translation>正在讀取…</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>writing…</source>
        <translation>正在寫入…</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>verified</source>
        <translation>已校驗</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>confirmed by its reply (cannot be read back)</source>
        <translation>已由應答確認（無法讀回）</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>not taken: the module holds %1</source>
        <translation>未生效：模組中的值為 %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>not confirmed: %1</source>
        <translation>未確認：%1</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>could not be read: %1</source>
        <translation>無法讀取：%1</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::ChartPanel</name>
    <message>
        <location filename="../ui/charts/chart_panel.cpp" line="+146"/>
        <source>Charts</source>
        <translation>圖表</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Choose the charts to show; they share the area</source>
        <translation>選擇要顯示的圖表；它們共用繪圖區域</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Window:</source>
        <translation>時間窗(&amp;W)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Time span shown by every chart</source>
        <translation>每個圖表顯示的時間跨度</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Run</source>
        <translation>執行</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Pause</source>
        <translation>暫停</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Follow the newest data again (Pause key)</source>
        <translation>重新跟隨最新資料（Pause 鍵）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Freeze every chart; the data keeps being recorded (Pause key)</source>
        <translation>凍結所有圖表；資料仍持續記錄（Pause 鍵）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Time axis:</source>
        <translation>時間軸(&amp;T)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Device clock</source>
        <translation>裝置時鐘</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Common time</source>
        <translation>共同時間</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Device clock: the module&apos;s own timestamps, where lost samples show as gaps. Common time: when each sample was taken, on this computer&apos;s clock (from the device&apos;s own clock where it has one, else when it arrived): every device on one time base.</source>
        <translation>裝置時鐘：模組自身的時間戳記，遺失的樣本會顯示為空缺。共同時間：每個樣本的取樣時刻，以這台電腦的時鐘表示（裝置有自身時鐘時據此換算，否則取樣本的到達時間）：所有裝置使用同一時間基準。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Cursor</source>
        <translation>游標</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A crosshair that follows the mouse and reads out every chart at the same time</source>
        <translation>跟隨滑鼠的十字線，同時讀出每個圖表的數值</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save all as PNG…</source>
        <translation>全部儲存為 PNG…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save the charts shown as one PNG image</source>
        <translation>將顯示的圖表儲存為一張 PNG 圖片</translation>
    </message>
    <message>
        <location line="+40"/>
        <source>This device&apos;s output carries no acceleration at its current setting.</source>
        <translation>該裝置目前設定下的輸出不含加速度。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>This device&apos;s output carries no angular rate at its current setting.</source>
        <translation>該裝置目前設定下的輸出不含角速度。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>This device&apos;s output carries no magnetic field at its current setting.</source>
        <translation>該裝置目前設定下的輸出不含磁場。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>This device&apos;s output carries no Euler angles at its current setting.</source>
        <translation>該裝置目前設定下的輸出不含歐拉角。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>This device&apos;s output carries no quaternion at its current setting.</source>
        <translation>該裝置目前設定下的輸出不含四元數。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>This device&apos;s output carries no pressure at its current setting.</source>
        <translation>該裝置目前設定下的輸出不含氣壓。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>This device&apos;s output carries no temperature at its current setting.</source>
        <translation>該裝置目前設定下的輸出不含溫度。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>This device&apos;s output carries no relative magnetic field at its current setting.</source>
        <translation>該裝置目前設定下的輸出不含相對磁場。</translation>
    </message>
    <message numerus="yes">
        <location line="+210"/>
        <source>%n chart(s) saved as one PNG in %1 (%2)</source>
        <translation>
            <numerusform>已將 %n 個圖表儲存為一張 PNG，位於 %1（%2）</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>imudesk::ui::ChartView</name>
    <message>
        <location filename="../ui/charts/chart_view.cpp" line="+91"/>
        <source>Accelerometer</source>
        <translation>加速度計</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Gyroscope</source>
        <translation>陀螺儀</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Magnetometer</source>
        <translation>磁力計</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Euler angles</source>
        <translation>歐拉角</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Quaternion</source>
        <translation>四元數</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Air pressure</source>
        <translation>氣壓</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+15"/>
        <source>Temperature</source>
        <translation>溫度</translation>
    </message>
    <message>
        <location line="-14"/>
        <source>Relative magnetic field</source>
        <translation>相對磁場</translation>
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
        <translation>磁場</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Angle</source>
        <translation>角度</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Quaternion component</source>
        <translation>四元數分量</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Pressure</source>
        <translation>氣壓</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Magnetic field (north = 1)</source>
        <translation>磁場（北向 = 1）</translation>
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
        <translation>裝置時間（s）</translation>
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
        <translation>無法繪製圖表</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Could not save the chart as %1: %2</source>
        <translation>無法將圖表儲存為 %1：%2</translation>
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
        <translation>按一下圖例中的軸可隱藏或顯示該軸；按右鍵可設定縱軸範圍並儲存此圖表</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Right-click for the vertical range and to save this chart</source>
        <translation>按右鍵可設定縱軸範圍並儲存此圖表</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Fit the vertical axis to the data shown; off: use the fixed range</source>
        <translation>縱軸自動適應顯示的資料；關閉時使用固定範圍</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Fixed range:</source>
        <translation>固定範圍：</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Fixed range (%1):</source>
        <translation>固定範圍（%1）：</translation>
    </message>
    <message>
        <location line="-2"/>
        <source>Auto scale</source>
        <translation>自動縮放</translation>
    </message>
    <message>
        <location line="-171"/>
        <source>Common time (s)</source>
        <translation>共同時間（s）</translation>
    </message>
    <message>
        <location line="+175"/>
        <source>Lower end of the vertical axis (no unit)</source>
        <translation>縱軸下限（無單位）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Upper end of the vertical axis (no unit)</source>
        <translation>縱軸上限（無單位）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Lower end of the vertical axis, in %1</source>
        <translation>縱軸下限，單位 %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Upper end of the vertical axis, in %1</source>
        <translation>縱軸上限，單位 %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Save as PNG…</source>
        <translation>另存為 PNG…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save this chart as a PNG image</source>
        <translation>將此圖表儲存為 PNG 影像</translation>
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
        <translation>將圖表儲存為 PNG</translation>
    </message>
    <message>
        <location line="-7"/>
        <source>PNG images (*.png)</source>
        <translation>PNG 影像 (*.png)</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::CommandLogWidget</name>
    <message>
        <location filename="../ui/workspace/command_log_widget.cpp" line="+170"/>
        <source>Copy</source>
        <translation>複製</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Copy the selected commands as tab-separated text</source>
        <translation>將所選指令複製為以定位字元分隔的文字</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Copy all</source>
        <translation>全部複製</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Copy every command as tab-separated text</source>
        <translation>將所有指令複製為以定位字元分隔的文字</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Clear</source>
        <translation>清除</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Remove every command from the list</source>
        <translation>從清單中移除所有指令</translation>
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
        <translation>在各裝置之間比較的物理量</translation>
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
        <translation>時間窗(&amp;W)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Time span shown</source>
        <translation>顯示的時間跨度</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Save as PNG…</source>
        <translation>另存為 PNG…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save this chart as a PNG image</source>
        <translation>將此圖表儲存為 PNG 影像</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Resume</source>
        <translation>繼續</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Pause</source>
        <translation>暫停</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Follow the newest data again</source>
        <translation>重新跟隨最新資料</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Freeze this chart; the data keeps being recorded</source>
        <translation>凍結此圖表；資料仍會繼續記錄</translation>
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
        <translation>東</translation>
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
        <translation>滾%1</translation>
    </message>
    <message numerus="yes">
        <location line="+12"/>
        <source>%n point(s)</source>
        <translation>
            <numerusform>%n 個點</numerusform>
        </translation>
    </message>
    <message>
        <location line="+17"/>
        <source>No attitude received yet</source>
        <translation>尚未收到姿態資料</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Heading %1°  pitch %2°  roll %3°</source>
        <translation>航向角 %1°  俯仰角 %2°  橫滾角 %3°</translation>
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
        <translation>%1 失敗：%2</translation>
    </message>
    <message>
        <location line="+40"/>
        <source>Read all</source>
        <translation>全部讀取</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Apply</source>
        <translation>套用</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save to flash</source>
        <translation>儲存到快閃記憶體</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Reboot</source>
        <translation>重新啟動</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Factory reset…</source>
        <translation>恢復出廠設定…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Mounting…</source>
        <translation>安裝方式…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Copy as command line</source>
        <translation>複製為命令列</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>absolute</source>
        <translation>絕對</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>relative</source>
        <translation>相對</translation>
    </message>
    <message>
        <location line="+2"/>
        <source> deg</source>
        <translation> deg</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1, firmware %2, serial %3 (%4)</source>
        <translation>%1，韌體 %2，序號 %3（%4）</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Not read yet: press Read all.</source>
        <translation>尚未讀取：請按「全部讀取」。</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>! %1</source>
        <translation>! %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>No pending changes.</source>
        <translation>沒有待套用的變更。</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Link: %1 of %2 bytes/s (%3 %) at %4 baud</source>
        <translation>鏈路：%1 / %2 位元組/秒（%3 %），波特率 %4</translation>
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
        <translation>輸出資料量超過鏈路容量</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Apply anyway?</source>
        <translation>仍要套用嗎？</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Factory reset</source>
        <translation>恢復出廠設定</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Go ahead?</source>
        <translation>確定要繼續嗎？</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::ConnectionBar</name>
    <message>
        <location filename="../ui/workspace/connection_bar.cpp" line="+190"/>
        <source>SN %1</source>
        <translation>序號 %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Manufacturer: %1</source>
        <translation>製造商：%1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>USB ID: %1:%2</source>
        <translation>USB ID：%1:%2</translation>
    </message>
    <message>
        <location line="+40"/>
        <source>&amp;Port:</source>
        <translation>串列埠(&amp;P)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Serial port of the IMU, or a simulated device that runs inside ImuDesk</source>
        <translation>IMU 所連接的串列埠，或在 ImuDesk 內部執行的模擬裝置</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Find devices…</source>
        <translation>尋找裝置…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Sweep every serial port and CAN bus for devices (Ctrl+Shift+F)</source>
        <translation>掃描所有序列埠和 CAN 匯流排上的裝置（Ctrl+Shift+F）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Refresh</source>
        <translation>重新整理</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Scan for serial ports again (the list also refreshes every 2 s)</source>
        <translation>重新掃描串列埠（清單也會每 2 s 自動重新整理）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Baud rate:</source>
        <translation>波特率(&amp;B)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Auto</source>
        <translation>自動</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Auto finds the device and the baud rate it talks at, starting with 115200</source>
        <translation>自動：找出裝置及其使用的鮑率，從 115200 開始</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Disconnect</source>
        <translation>中斷連線</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Close the connection (Ctrl+D)</source>
        <translation>關閉連線（Ctrl+D）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Connect</source>
        <translation>連線</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Connect to the selected port (Ctrl+K)</source>
        <translation>連線到所選串列埠（Ctrl+K）</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Simulated %1</source>
        <translation>模擬 %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Simulated %1 (firmware %2)</source>
        <translation>模擬 %1（韌體 %2）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 (%2)</source>
        <translation>%1（%2）</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>No serial port found</source>
        <translation>找不到串列埠</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>A simulated device on a pseudo-terminal, driven exactly like hardware</source>
        <translation>執行在虛擬終端機上的模擬裝置，操作方式與真實硬體完全相同</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::ConsoleWidget</name>
    <message>
        <location filename="../ui/workspace/console_widget.cpp" line="+88"/>
        <source>(reply to: %1)</source>
        <translation>（對 %1 的回應）</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>ERR: %1</source>
        <translation>錯誤：%1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Invalid reply: %1</source>
        <translation>無效應答：%1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Timeout: %1</source>
        <translation>逾時：%1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cancelled: %1</source>
        <translation>已取消：%1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Not sent: %1</source>
        <translation>未傳送：%1</translation>
    </message>
    <message>
        <location line="+59"/>
        <source>Type an ASCII command, e.g. LOG VERSION, and press Enter</source>
        <translation>輸入 ASCII 指令（例如 LOG VERSION）後按 Enter</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Enter sends the command; Up and Down recall earlier commands</source>
        <translation>Enter 傳送指令；上、下方向鍵叫出先前的指令</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Send</source>
        <translation>傳送</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Clear log</source>
        <translation>清除日誌</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::CorrelationPlot</name>
    <message>
        <location filename="../ui/recording/twist_align_dialog.cpp" line="+168"/>
        <source>Normalised cross-correlation of each device&apos;s gyro magnitude with the reference&apos;s, against the shift of its time (ms). The marker is the offset found; a good match peaks close to 1.</source>
        <translation>各裝置陀螺儀角速度大小與參考裝置的正規化互相關，隨該裝置時間平移量（ms）的變化曲線。標記處為求得的偏移；匹配良好時峰值接近 1。</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>Find offsets to see how each device&apos;s gyro magnitude matches the reference&apos;s.</source>
        <translation>按「計算偏移」後，可在此查看各裝置的陀螺儀角速度大小與參考裝置的匹配情形。</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>Correlation</source>
        <translation>相關係數</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Shift of the device&apos;s time (ms)</source>
        <translation>裝置時間平移（ms）</translation>
    </message>
    <message>
        <location line="+51"/>
        <source>least correlation accepted</source>
        <translation>可接受的最低相關係數</translation>
    </message>
    <message>
        <location line="+41"/>
        <source>%1: %2 ms, correlation %3</source>
        <translation>%1：%2 ms，相關係數 %3</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1: not aligned</source>
        <translation>%1：未對齊</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::DeviceWorkspace</name>
    <message>
        <location filename="../ui/workspace/device_workspace.cpp" line="+365"/>
        <source>New connection</source>
        <translation>新連線</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 on %2</source>
        <translation>%2 上的 %1</translation>
    </message>
    <message>
        <location line="+124"/>
        <source>Reference %1° apart (±%2°)</source>
        <translation>參考姿態相差 %1°（±%2°）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Reference: hold the module still for 1 s to start it</source>
        <translation>參考姿態：讓模組靜止 1 s 以啟動</translation>
    </message>
    <message>
        <location line="+108"/>
        <source>Frames arrive again on %1.</source>
        <translation>%1 上又收到幀了。</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Not connected</source>
        <translation>未連線</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Opening %1…</source>
        <translation>正在開啟 %1…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Detecting the baud rate of %1…</source>
        <translation>正在偵測 %1 的波特率…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Connected</source>
        <translation>已連線</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Connection to %1 lost</source>
        <translation>與 %1 的連線已中斷</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Disconnected from %1 — waiting for the device to come back</source>
        <translation>已與 %1 中斷連線，正在等待裝置重新連線</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Could not connect to %1</source>
        <translation>無法連線到 %1</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>firmware %1</source>
        <translation>韌體 %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>SN %1</source>
        <translation>序號 %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>world frame %1 assumed</source>
        <translation>假定世界座標系 %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Product: %1</source>
        <translation>產品：%1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Build: %1</source>
        <translation>建置：%1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Bootloader: %1</source>
        <translation>開機載入程式：%1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The module&apos;s LOG COMCONFIG reply names no COORD: its attitude is drawn as %1, the default, which it did not confirm (CONFIG IMU COORD sets it)</source>
        <translation>模組的 LOG COMCONFIG 回覆中沒有 COORD：其姿態按預設的 %1 顯示，但模組並未確認（可用 CONFIG IMU COORD 設定）</translation>
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
        <translation>無數據幀</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>load %1%</source>
        <translation>負載 %1%</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>CRC errors %1</source>
        <translation>CRC 錯誤 %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>lost %1</source>
        <translation>遺失 %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>skipped %1 B</source>
        <translation>略過 %1 B</translation>
    </message>
    <message>
        <location line="+5"/>
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
        <location line="+55"/>
        <source>Console</source>
        <translation>主控台</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Raw bytes</source>
        <translation>原始位元組</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Command log</source>
        <translation>指令日誌</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Values</source>
        <translation>數值</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Details</source>
        <translation>詳情</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>3D attitude</source>
        <translation>3D 姿態</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Time sync</source>
        <translation>時間同步</translation>
    </message>
    <message>
        <location filename="../ui/workspace/device_workspace_layout.cpp" line="+168"/>
        <source>&amp;Monitor</source>
        <translation>監看(&amp;M)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>C&amp;onfigure</source>
        <translation>設定(&amp;O)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>C&amp;alibrate</source>
        <translation>校準(&amp;A)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A&amp;nalyse</source>
        <translation>分析(&amp;N)</translation>
    </message>
    <message>
        <location line="+165"/>
        <source>%1 was floating off the screen</source>
        <translation>%1 浮動在螢幕之外</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 is not used by this link</source>
        <translation>此連線不使用 %1</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>the charts were squeezed</source>
        <translation>圖表被擠壓</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the 3D attitude view was squeezed</source>
        <translation>3D 姿態檢視被擠壓</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the values table was squeezed</source>
        <translation>數值表被擠壓</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>the values table was too narrow for its columns</source>
        <translation>數值表太窄，無法容納其各欄</translation>
    </message>
    <message>
        <location filename="../ui/workspace/device_workspace.cpp" line="-2"/>
        <source>Configuration</source>
        <translation>配置</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Recording</source>
        <translation>記錄</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::ExportDialog</name>
    <message>
        <location filename="../ui/recording/export_dialog.cpp" line="+130"/>
        <source>Export %1</source>
        <translation>匯出 %1</translation>
    </message>
    <message>
        <location line="-98"/>
        <source>The capture to export: a recording, a vendor CSV or a raw byte dump; or a recorded session&apos;s folder (or its session.json): every device, aligned in one file</source>
        <translation>要匯出的擷取：錄製檔、廠商 CSV 或原始位元組傾印；或已錄製工作階段的資料夾（或其 session.json）：所有裝置對齊寫入一個檔案</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Choose…</source>
        <translation>選擇…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Export another capture</source>
        <translation>匯出另一個擷取</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Vendor CSV (the vendor tool&apos;s layout; a file per frame type when there are several)</source>
        <translation>廠商 CSV（廠商工具的格式；有多種幀類型時每種一個檔案）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Tidy CSV (pandas, PlotJuggler)</source>
        <translation>整潔 CSV（適用 pandas、PlotJuggler）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>JSON Lines</source>
        <translation>JSON 逐行格式（jsonl）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>MCAP (ROS 2: PlotJuggler, Foxglove, Lichtblick)</source>
        <translation>MCAP（ROS 2：PlotJuggler、Foxglove、Lichtblick）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>MATLAB .mat (a struct per device, SI units)</source>
        <translation>MATLAB .mat（每台裝置一個結構，國際單位制）</translation>
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
        <translation>結尾</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Export</source>
        <translation>匯出</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Show in folder</source>
        <translation>在資料夾中顯示</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Open the folder of the written file in the file manager</source>
        <translation>在檔案管理員中開啟所寫檔案的資料夾</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Capture:</source>
        <translation>擷取：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Format:</source>
        <translation>格式：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Output:</source>
        <translation>輸出：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>From:</source>
        <translation>開始：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>To:</source>
        <translation>結束：</translation>
    </message>
    <message>
        <location line="+46"/>
        <source>Export the session %1</source>
        <translation>匯出工作階段 %1</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>A recorded session is exported whole, every device aligned on the session&apos;s time base</source>
        <translation>已錄製的工作階段整體匯出，所有裝置依工作階段的時間基準對齊</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Export capture</source>
        <translation>匯出擷取</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Captures, sessions, vendor CSV and raw dumps (*.imucap session.json *.csv *.bin *.raw *.log *.dat *.txt);;All files (*)</source>
        <translation>擷取、工作階段、廠商 CSV 與原始傾印 (*.imucap session.json *.csv *.bin *.raw *.log *.dat *.txt);;所有檔案 (*)</translation>
    </message>
    <message>
        <location line="+45"/>
        <source>Exporting…</source>
        <translation>正在匯出…</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <location line="+57"/>
        <source>Export cancelled; the partial files were removed.</source>
        <translation>匯出已取消；已刪除未完成的檔案。</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Close</source>
        <translation>關閉</translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>%n row(s) written to %1</source>
        <translation>
            <numerusform>已將 %n 列寫入 %1</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>imudesk::ui::FindDevicesDialog</name>
    <message numerus="yes">
        <location filename="../ui/discovery/find_devices_dialog.cpp" line="+142"/>
        <source>%n device(s) opened, each in a tab of its own.</source>
        <translation>
            <numerusform>已開啟 %n 台裝置，每台在單獨的分頁中。</numerusform>
        </translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Find devices</source>
        <translation>尋找裝置</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>One sweep of every serial port and CAN bus: each serial family at its rates, silent ports as Modbus RTU lines, CAN buses listened to before anything is sent. Nothing is written to a device and every port is closed afterwards.</source>
        <translation>一次掃描所有序列埠和 CAN 匯流排：依各序列埠裝置系列的鮑率逐一嘗試，無回應的連接埠作為 Modbus RTU 線路詢問，CAN 匯流排先監聽再傳送。不會向裝置寫入任何內容，結束後關閉所有連接埠。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>More &amp;serial ports:</source>
        <translation>更多序列埠(&amp;S)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>beside the machine&apos;s, comma-separated, e.g. /dev/pts/3,/dev/ttyUSB4</source>
        <translation>本機序列埠以外的連接埠，以逗號分隔，例如 /dev/pts/3,/dev/ttyUSB4</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ports the machine does not list, such as pseudo-terminals</source>
        <translation>本機未列出的連接埠，例如虛擬終端</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;CAN buses:</source>
        <translation>CAN 匯流排(&amp;C)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PLUGIN:INTERFACE, comma-separated, e.g. socketcan:can1,virtualcan:can0</source>
        <translation>外掛:介面，以逗號分隔，例如 socketcan:can1,virtualcan:can0</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Every socketcan interface is swept anyway; name the others here</source>
        <translation>所有 socketcan 介面都會被掃描；其他介面請在此填寫</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Only these</source>
        <translation>僅掃描這些(&amp;O)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Sweep only the ports and buses named above, not every serial port and socketcan interface of the machine</source>
        <translation>只掃描上面列出的連接埠和匯流排，不掃描本機所有序列埠和 socketcan 介面</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Ask silent ports as &amp;Modbus lines</source>
        <translation>將無回應連接埠作為 &amp;Modbus 線路詢問</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ids 80 and 1 at every rate first, then ids 1-247 at each rate, fastest first, until a device answers or the time is up</source>
        <translation>先在每個鮑率下詢問 ID 80 和 1，再從最快的鮑率開始逐個詢問 ID 1-247，直到有裝置回應或時間用完</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Time limit:</source>
        <translation>時間上限(&amp;T)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The whole sweep at most, in seconds</source>
        <translation>整個掃描的最長時間，單位為秒</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Simulated &amp;bench</source>
        <translation>模擬測試台(&amp;B)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Start simulated devices to find: a HiPNUC module at 460800 baud, an HEC495 at 4800 baud address 7, a Modbus module at 38400 baud id 17, a silent port, and on virtualcan can1 a J1939 module and two CANopen modules sharing node 5</source>
        <translation>啟動供尋找的模擬裝置：一個鮑率 460800 的 HiPNUC 模組，一個鮑率 4800、位址 7 的 HEC495，一個鮑率 38400、ID 17 的 Modbus 模組，一個無回應連接埠，以及 virtualcan can1 上的一個 J1939 模組和兩個共用節點 5 的 CANopen 模組</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Sweep</source>
        <translation>掃描(&amp;S)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Start the sweep (F5)</source>
        <translation>開始掃描（F5）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Connect &amp;all</source>
        <translation>全部連線(&amp;A)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Open every device found in a tab of its own</source>
        <translation>在各自的分頁中開啟找到的每台裝置</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Close</source>
        <translation>關閉</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Conflicts and ports where nothing was found:</source>
        <translation>衝突及未找到裝置的連接埠：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Link</source>
        <translation>鏈路</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Port</source>
        <translation>連接埠</translation>
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
        <translation>型號</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Serial number</source>
        <translation>序號</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Address / node</source>
        <translation>位址 / 節點</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Firmware</source>
        <translation>韌體</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Serial: baud; CAN: bit/s</source>
        <translation>序列埠：鮑率；CAN：bit/s</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+176"/>
        <source>Connect</source>
        <translation>連線</translation>
    </message>
    <message>
        <location line="-174"/>
        <source>Press Sweep to look at every port and bus.</source>
        <translation>按「掃描」檢查所有連接埠和匯流排。</translation>
    </message>
    <message>
        <location line="+100"/>
        <source>&quot;%1&quot; is not PLUGIN:INTERFACE (e.g. socketcan:can0): correct the CAN buses field.</source>
        <translation>「%1」不是 外掛:介面 格式（例如 socketcan:can0）：請更正 CAN 匯流排一欄。</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>No serial port and no CAN bus to sweep: plug in an adapter, or name ports and buses above (or tick Simulated bench).</source>
        <translation>沒有可掃描的序列埠或 CAN 匯流排：請插入轉接器，或在上方填寫連接埠和匯流排（或勾選「模擬測試台」）。</translation>
    </message>
    <message numerus="yes">
        <location line="+4"/>
        <source>Sweeping %n port(s)</source>
        <translation>
            <numerusform>正在掃描 %n 個連接埠</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+0"/>
        <source> and %n CAN bus(es)…</source>
        <translation>
            <numerusform>和 %n 條 CAN 匯流排…</numerusform>
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
        <translation>序列埠</translation>
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
        <translation>在此鮑率下監聽無錯誤</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 baud</source>
        <translation>%1 鮑</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>node %1</source>
        <translation>節點 %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Open this device in a tab of its own</source>
        <translation>在單獨的分頁中開啟此裝置</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Could not connect %1: %2</source>
        <translation>無法連線 %1：%2</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 opened in its own tab.</source>
        <translation>%1 已在單獨的分頁中開啟。</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Two devices at this address: %1</source>
        <translation>此位址上有兩台裝置：%1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Conflict on %1, %2 %3: %4 What to do: %5</source>
        <translation>%1 上的衝突，%2 %3：%4 處理方法：%5</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>node</source>
        <translation>節點</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>address</source>
        <translation>位址</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>busy</source>
        <translation>被佔用</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>silent</source>
        <translation>無回應</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>garbage</source>
        <translation>亂碼</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no permission</source>
        <translation>無權限</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>could not open</source>
        <translation>無法開啟</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>out of time</source>
        <translation>逾時</translation>
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
            <numerusform>找到 %n 台裝置</numerusform>
        </translation>
    </message>
    <message>
        <location line="+0"/>
        <source> in %1 s.</source>
        <translation>，用時 %1 s。</translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source> %n conflict(s): see below, in red.</source>
        <translation>
            <numerusform> %n 處衝突：見下方紅色部分。</numerusform>
        </translation>
    </message>
    <message>
        <location line="+2"/>
        <source> Cancelled: what was found so far is listed.</source>
        <translation>已取消：列出的是目前已找到的裝置。</translation>
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
        <translation>%1 上的韌體更新</translation>
    </message>
    <message>
        <location line="-161"/>
        <source>Serial port %1 (KBOOT bootloader)</source>
        <translation>串列埠 %1（KBOOT 開機載入程式）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CAN bus (CANopen SDO to object 0x1F51)</source>
        <translation>CAN 匯流排（CANopen SDO 寫入物件 0x1F51）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>How the firmware reaches the module: its serial port, or a CAN adapter on the module&apos;s CANopen bus</source>
        <translation>韌體傳送到模組的方式：透過模組的串列埠，或透過接在模組 CANopen 匯流排上的 CAN 轉接器</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Link:</source>
        <translation>鏈路：</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Intel HEX (.hex) or raw binary (.bin)</source>
        <translation>Intel HEX（.hex）或原始二進位檔（.bin）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Choose...</source>
        <translation>選擇...</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Demo image</source>
        <translation>示範韌體</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Simulated module only: write an application image of firmware 1.7.2 that the simulated bootloader accepts, and choose it</source>
        <translation>僅限模擬模組：寫入一個韌體版本 1.7.2 的應用程式映像（模擬開機載入程式可接受）並選取它</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>File:</source>
        <translation>檔案：</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>A .bin file has no addresses: the flash address of its first byte</source>
        <translation>.bin 檔案不含位址：請填寫其第一個位元組的快閃記憶體位址</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Start of a .bin:</source>
        <translation>.bin 起始位址：</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>no file chosen</source>
        <translation>未選擇檔案</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Image:</source>
        <translation>映像檔：</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1, firmware %2, bootloader %3</source>
        <translation>%1，韌體 %2，開機載入程式 %3</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>read when the update starts</source>
        <translation>開始更新時讀取</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Module:</source>
        <translation>模組：</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+252"/>
        <source>ready</source>
        <translation>就緒</translation>
    </message>
    <message>
        <location line="-250"/>
        <source>Step:</source>
        <translation>步驟：</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Progress:</source>
        <translation>進度：</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Speed:</source>
        <translation>速度：</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Update</source>
        <translation>更新</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+299"/>
        <source>Close</source>
        <translation>關閉</translation>
    </message>
    <message>
        <location line="-264"/>
        <source>CAN bus</source>
        <translation>CAN 匯流排</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>The Qt CAN bus plugin of the adapter (socketcan for Linux CAN interfaces)</source>
        <translation>轉接器對應的 Qt CAN 匯流排外掛程式（Linux CAN 介面用 socketcan）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Plugin:</source>
        <translation>外掛程式：</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The adapter&apos;s interface name, e.g. can0</source>
        <translation>轉接器的介面名稱，例如 can0</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Interface:</source>
        <translation>介面：</translation>
    </message>
    <message>
        <location line="+6"/>
        <source> bit/s</source>
        <translation> bit/s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>as configured</source>
        <translation>沿用介面設定</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The bus bit rate in bit/s (the HiPNUC CANopen default is 500000 bit/s); 0 leaves the interface&apos;s setting</source>
        <translation>匯流排位元速率，單位 bit/s（HiPNUC CANopen 預設為 500000 bit/s）；0 表示沿用介面目前的設定</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Bit rate:</source>
        <translation>位元速率：</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The module&apos;s CANopen node ID, 1..127 (HiPNUC default 8)</source>
        <translation>模組的 CANopen 節點 ID，1..127（HiPNUC 預設為 8）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Node:</source>
        <translation>節點：</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>Firmware update over CAN</source>
        <translation>透過 CAN 更新韌體</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>The demo image could not be written to %1: %2. Free some space in the temporary folder and try again.</source>
        <translation>無法將示範韌體寫入 %1：%2。請清出暫存資料夾的空間後重試。</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Choose the firmware</source>
        <translation>選擇韌體</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Firmware (*.hex *.ihex *.bin);;All files (*)</source>
        <translation>韌體 (*.hex *.ihex *.bin);;所有檔案 (*)</translation>
    </message>
    <message>
        <location line="+16"/>
        <location line="+7"/>
        <source>refused: %1</source>
        <translation>已拒絕：%1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 bytes from %2 to %3, CRC-32 %4; target model: not recorded in the file</source>
        <translation>%1 位元組，位址 %2 至 %3，CRC-32 %4；目標型號：檔案中未記錄</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>waiting for the tab to close the port...</source>
        <translation>正在等待分頁關閉連接埠...</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>cancelling after the current packet...</source>
        <translation>將在目前封包完成後取消...</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>%1 of %2 bytes</source>
        <translation>%1 / %2 位元組</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 bytes/s</source>
        <translation>%1 位元組/秒</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 bytes/s, %2 s left</source>
        <translation>%1 位元組/秒，剩餘 %2 s</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>firmware %1 → %2 (new); verification: %3</source>
        <translation>韌體 %1 → %2（新）；驗證方式：%3</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>CRC-32 reported by the bootloader</source>
        <translation>開機載入程式回報的 CRC-32</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>none by the bootloader; the application restarted</source>
        <translation>開機載入程式未驗證；應用程式已重新啟動</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1, firmware %2 (new), bootloader %3</source>
        <translation>%1，韌體 %2（新），開機載入程式 %3</translation>
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
        <translation>未更新：%1</translation>
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
        <translation>陀螺儀標度因數校準</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Preparation</source>
        <translation>準備</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&lt;ul&gt;&lt;li&gt;Place the module, with the robot or vehicle it is fixed to, on a level, flat floor.&lt;/li&gt;&lt;li&gt;Keep the temperature steady and avoid vibration (motors off).&lt;/li&gt;&lt;li&gt;Mark the start position: you must stop on the same mark, within 5 deg.&lt;/li&gt;&lt;li&gt;Turn at an even 20-100 deg/s (5-20 s per turn), in either direction, without pausing.&lt;/li&gt;&lt;li&gt;More turns give a smaller error: 720 deg (2 turns) to 1800 deg (5 turns).&lt;/li&gt;&lt;/ul&gt;Keep the module still for a few seconds after pressing Start: ImuDesk measures the gyro bias first.</source>
        <translation>&lt;ul&gt;&lt;li&gt;將模組連同其固定的機器人或車輛放在水平、平整的地面上。&lt;/li&gt;&lt;li&gt;保持溫度穩定並避免振動（關閉馬達）。&lt;/li&gt;&lt;li&gt;標記起始位置：必須停在同一標記處，誤差在 5 deg 以內。&lt;/li&gt;&lt;li&gt;以 20-100 deg/s 的均勻轉速轉動（每圈 5-20 s），方向不限，中途不要停頓。&lt;/li&gt;&lt;li&gt;圈數越多誤差越小：720 deg（2 圈）至 1800 deg（5 圈）。&lt;/li&gt;&lt;/ul&gt;按下「開始」後請保持模組靜止幾秒：ImuDesk 會先測量陀螺儀零偏。</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Turn on HI91 at 100 Hz (LOG HI91 ONTIME 0.01)</source>
        <translation>以 100 Hz 開啟 HI91（LOG HI91 ONTIME 0.01）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Sends LOG HI91 ONTIME 0.01: the float IMU frame, gyroscope included, every 10 ms. Until SAVECONFIG it lasts until the module restarts.</source>
        <translation>傳送 LOG HI91 ONTIME 0.01：每 10 ms 輸出一幀浮點 IMU 資料（含陀螺儀）。未執行 SAVECONFIG 時，模組重新啟動後失效。</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Turn the module</source>
        <translation>轉動模組</translation>
    </message>
    <message>
        <location line="+6"/>
        <source> deg</source>
        <translation> deg</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Start</source>
        <translation>開始</translation>
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
        <translation>轉速 %v deg/s（範圍 20-100）</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Angle:</source>
        <translation>角度：</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>Result</source>
        <translation>結果</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>The module refused LOG HI91 ONTIME 0.01 (%1). Check the output in Device ▸ Configuration.</source>
        <translation>模組拒絕了 LOG HI91 ONTIME 0.01（%1）。請在「裝置 ▸ 配置」中檢查輸出設定。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>no answer</source>
        <translation>無回應</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Gyroscope data: checking what the module sends…</source>
        <translation>陀螺儀資料：正在檢查模組的輸出…</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>Gyroscope data: %1 Hz. Ready: ImuDesk will follow the turn.</source>
        <translation>陀螺儀資料：%1 Hz。就緒：ImuDesk 將追蹤轉動過程。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>No gyroscope data arrives: the module&apos;s calibration still works, but ImuDesk cannot show the angle turned or when to stop. Turn the HI91 output on.</source>
        <translation>未收到陀螺儀資料：模組本身的校準仍可進行，但 ImuDesk 無法顯示已轉過的角度與停止時機。請開啟 HI91 輸出。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Gyroscope data: %1 Hz, too slow to follow the turn (ImuDesk needs %2 Hz or more). Turn the HI91 output on at 100 Hz.</source>
        <translation>陀螺儀資料：%1 Hz，太慢，無法追蹤轉動（ImuDesk 需要 %2 Hz 或以上）。請以 100 Hz 開啟 HI91 輸出。</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Sending LOG HI91 ONTIME 0.01…</source>
        <translation>正在傳送 LOG HI91 ONTIME 0.01…</translation>
    </message>
    <message>
        <location line="+67"/>
        <source>%1 deg turned (%2 turns), rate %3 deg/s %4</source>
        <translation>已轉動 %1 deg（%2 圈），轉速 %3 deg/s %4</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>(in band)</source>
        <translation>（範圍內）</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>(outside 20-100 deg/s)</source>
        <translation>（超出 20-100 deg/s）</translation>
    </message>
    <message>
        <location line="+54"/>
        <source>The device rejected the run: %1</source>
        <translation>裝置拒絕本輪結果：%1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The device accepted the run, but ImuDesk saw no complete turn to check it.</source>
        <translation>裝置已接受本輪結果，但 ImuDesk 未偵測到完整的轉動，無法驗證。</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>The device accepted the calibration (OK).</source>
        <translation>裝置已接受校準（OK）。</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>The device rejected the run (ERR).</source>
        <translation>裝置拒絕本輪結果（ERR）。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>ImuDesk&apos;s estimate from the same samples: %1</source>
        <translation>ImuDesk 根據相同樣本的估計：%1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>ImuDesk saw no complete turn, so it has no estimate of its own.</source>
        <translation>ImuDesk 未偵測到完整的轉動，因此無法自行估計。</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::HeadingDial</name>
    <message>
        <location filename="../ui/attitude/heading_dial.cpp" line="+25"/>
        <source>Heading dial</source>
        <translation>航向角錶盤</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>%1°</source>
        <translation>%1°</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>no data</source>
        <translation>無資料</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>pitch %1°  roll %2°</source>
        <translation>俯仰角 %1°  橫滾角 %2°</translation>
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
        <translation>適用：羅盤及其安裝座可轉到表中的各個姿態。效果良好；在複雜磁場環境下精度略低於全姿態校準。限制：俯仰角需超過 45 deg，橫滾角需超過 30 deg。手冊建議優先嘗試此方法。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Suits: the pitch and roll range of use is known; collect most points in the poses used most. Best at the chosen points; badly chosen points can spoil the calibration.</source>
        <translation>適用：已知使用時的俯仰角和橫滾角範圍；在最常用的姿態採集大部分點。在所選點上效果最佳；點選得不好可能使校準變差。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Suits: the compass and its mount can turn to every orientation and the magnetic environment is complex. The most accurate over all attitudes.</source>
        <translation>適用：羅盤及其安裝座可轉到任意姿態，且磁場環境複雜。在所有姿態下精度最高。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Suits: roll stays below 5 deg in use while pitch varies widely. Best when roll is below 5 deg. Limit: pitch must exceed 45 deg.</source>
        <translation>適用：使用時橫滾角保持在 5 deg 以下，而俯仰角變化較大。橫滾角小於 5 deg 時效果最佳。限制：俯仰角需超過 45 deg。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Suits: the compass only turns in a plane, pitch and roll below 2 deg. Best when it is used level.</source>
        <translation>適用：羅盤只在平面內轉動，俯仰角和橫滾角小於 2 deg。水平使用時效果最佳。</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>HEC495 compass calibration</source>
        <translation>HEC495 羅盤校準</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Choose the calibration method</source>
        <translation>選擇校準方法</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Calibrate in the place of use, with the compass fixed in its mount: everything near it (iron, batteries, motors, cables with current) must turn together with it. Carry no phone, keys or other metal while calibrating.</source>
        <translation>請在使用地點校準，並將羅盤固定在安裝座上：其附近的所有物件（鐵件、電池、馬達、通電的電纜）都必須與它一起轉動。校準時請勿攜帶手機、鑰匙或其他金屬物品。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 (command 0x%2)</source>
        <translation>%1（指令 0x%2）</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Calibrate</source>
        <translation>校準</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Targets: inner ring pitch up (above 45 deg), middle ring level, outer ring pitch down (below -45 deg); R is the roll to hold. Green: collected; orange outline: the target the compass is at. The red needle is the heading, the blue dot the pitch, the bar below the roll.</source>
        <translation>目標：內圈為仰（俯仰角大於 45 deg），中圈為水平，外圈為俯（俯仰角小於 -45 deg）；「滾」為需保持的橫滾角。綠色：已採集；橙色外框：羅盤目前所在的目標。紅色指針為航向角，藍色圓點為俯仰角，下方長條為橫滾角。</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Start calibration</source>
        <translation>開始校準</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Collect point</source>
        <translation>採集點</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stop</source>
        <translation>停止</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save calibration</source>
        <translation>儲存校準</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Clear calibration</source>
        <translation>清除校準</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Sends the start command of the method (77 04 00 xx).</source>
        <translation>傳送此方法的啟動指令（77 04 00 xx）。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Manual method: stores the current pose as a calibration point (0x67).</source>
        <translation>手動方法：將目前姿態存為一個校準點（0x67）。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Abandons the run without saving (0x12).</source>
        <translation>放棄本次校準，不儲存（0x12）。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Computes and stores the calibration from the points collected (0x09).</source>
        <translation>根據已採集的點計算並儲存校準（0x09）。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Erases the environment calibration stored in the module (0x10).</source>
        <translation>清除模組中儲存的環境校準（0x10）。</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Save to the compass</source>
        <translation>儲存到羅盤</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Not yet</source>
        <translation>暫不儲存</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Keeps the run going: turn the compass to more targets, or stop without saving.</source>
        <translation>繼續本次校準：將羅盤轉到更多目標姿態，或停止而不儲存。</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>The module collected %1 points (at most %2) by itself. Saving computes the calibration from them and replaces the compass&apos;s current calibration; this cannot be undone. Save now?</source>
        <translation>模組已自動採集 %1 個點（最多 %2 個）。儲存將據此計算校準並取代羅盤目前的校準，且無法復原。現在儲存嗎？</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Not saved yet: the run goes on.</source>
        <translation>尚未儲存：校準繼續進行。</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Result</source>
        <translation>結果</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Calibrate again</source>
        <translation>重新校準</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Then save: the module replies with its fit error (FitErr); the smaller the better, above %1 calibrate again.</source>
        <translation>然後儲存：模組會回覆其擬合誤差（FitErr）；越小越好，超過 %1 請重新校準。</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Method: %1</source>
        <translation>方法：%1</translation>
    </message>
    <message>
        <location line="+48"/>
        <source>Starting the calibration...</source>
        <translation>正在啟動校準...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Collecting a point...</source>
        <translation>正在採集點...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stopping the calibration...</source>
        <translation>正在停止校準...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Saving the calibration...</source>
        <translation>正在儲存校準...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Clearing the stored calibration...</source>
        <translation>正在清除已儲存的校準...</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Calibration running (%1). Turn the compass as shown; targets light up as the module collects points.</source>
        <translation>校準進行中（%1）。請依圖示轉動羅盤；模組採集到點時，對應目標會亮起。</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Point collected.</source>
        <translation>已採集點。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Calibration stopped; nothing was saved. The module keeps its previous calibration.</source>
        <translation>校準已停止，未儲存任何資料。模組保留先前的校準。</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The stored environment calibration was cleared from the module. Start a new calibration before relying on the heading near iron.</source>
        <translation>已清除模組中儲存的環境校準。在鐵件附近依賴航向角之前，請先重新校準。</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Calibration saved.</source>
        <translation>校準已儲存。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The module answered the save command without a fit error (%1). Collect the points again and save once more.</source>
        <translation>模組回覆儲存指令時未附擬合誤差（%1）。請重新採集點並再次儲存。</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>Check the cable, the power, the baud rate and the module address, then try again.</source>
        <translation>請檢查電纜、電源、波特率和模組位址，然後重試。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The connection is closed: connect to the compass again, then restart the calibration.</source>
        <translation>連線已關閉：請重新連線到羅盤，然後重新開始校準。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The reply was not one the manual allows: check that the device is an HEC495 and try again.</source>
        <translation>回覆不符合手冊規定：請確認裝置為 HEC495，然後重試。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The module could not compute a calibration: too few points, or points that do not span the field. Start the calibration again and turn through more of the target poses before saving.</source>
        <translation>模組無法計算校準：點數太少，或點未能涵蓋整個磁場。請重新開始校準，並在儲存前轉過更多目標姿態。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The module did not take the point: no manual calibration is running, or it is full. Start the manual method first.</source>
        <translation>模組未接受該點：沒有正在進行的手動校準，或點數已滿。請先啟動手動方法。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The module refused to start this method. Stop any calibration in progress and try again.</source>
        <translation>模組拒絕啟動此方法。請停止進行中的校準，然後重試。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Try again; if it keeps failing, power the module off and on.</source>
        <translation>請重試；若仍然失敗，請將模組斷電後重新上電。</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Failed: %1.
%2</source>
        <translation>失敗：%1。
%2</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Valid points: %1 of at most %2</source>
        <translation>有效點：%1 個（最多 %2 個）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Valid points: %1 (at least %2)</source>
        <translation>有效點：%1 個（至少 %2 個）</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>No calibration was saved.</source>
        <translation>未儲存任何校準。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Fit error (FitErr): %1
Points used: %2
Method: %3</source>
        <translation>擬合誤差（FitErr）：%1
使用點數：%2
方法：%3</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>FitErr is above %1: the manual says to calibrate again. Check that nothing magnetic moved relative to the compass during the run, that no phone or keys were near, and turn through the target poses more carefully; press &quot;Calibrate again&quot;.</source>
        <translation>FitErr 高於 %1：手冊要求重新校準。請確認校準過程中沒有磁性物體相對羅盤移動、附近沒有手機或鑰匙，並更仔細地轉過各目標姿態；然後按「重新校準」。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Good: FitErr is at most %1. The module stores and uses the calibration from now on.</source>
        <translation>良好：FitErr 不超過 %1。模組將儲存並自此使用此校準。</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>FitErr %1 is at most %2.</source>
        <translation>FitErr %1 不超過 %2。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>FitErr %1 is above %2: the manual says to calibrate again.</source>
        <translation>FitErr %1 高於 %2：手冊要求重新校準。</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::Hec495SettingsPanel</name>
    <message>
        <location filename="../ui/configuration/hec495_settings_panel.cpp" line="+130"/>
        <source>Factory reset</source>
        <translation>恢復出廠設定</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Restore the factory settings (9600 baud, address 0, declination 0, question/answer)? The session follows the module to 9600 baud.</source>
        <translation>要恢復出廠設定嗎（波特率 9600、位址 0、磁偏角 0、問答模式）？連線會隨模組切換到波特率 9600。</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Waiting for the module…</source>
        <translation>正在等待模組…</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Failed: %1</source>
        <translation>失敗：%1</translation>
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
        <translation>輸出速率</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Output content</source>
        <translation>輸出內容</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Module address</source>
        <translation>模組位址</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Single reading</source>
        <translation>單次讀取</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Read</source>
        <translation>讀取</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ask the module for its address (manual 2.17: sent to address 0, any module answers).</source>
        <translation>向模組查詢其位址（手冊 2.17：發往位址 0，任何模組都會回應）。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ask the module once for the chosen angle (manual 2.1 to 2.4); the answer, in degrees, shows below.</source>
        <translation>向模組讀取一次所選角度（手冊 2.1 至 2.4）；回應（單位為度）顯示在下方。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Pitch</source>
        <translation>俯仰</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Roll</source>
        <translation>橫滾</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Heading</source>
        <translation>航向</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Pitch, roll and heading</source>
        <translation>俯仰、橫滾和航向</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Set</source>
        <translation>設定</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save settings</source>
        <translation>儲存設定</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Factory reset…</source>
        <translation>恢復出廠設定…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Changes apply at once and are lost at power-off unless saved.</source>
        <translation>變更會立即生效；若未儲存，斷電後即遺失。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Question/answer</source>
        <translation>問答模式</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1 Hz</source>
        <translation>%1 Hz</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Default (angles)</source>
        <translation>預設（角度）</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Internal data</source>
        <translation>內部資料</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>All data (read-all record)</source>
        <translation>全部資料（全讀記錄）</translation>
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
        <translation>未知語言「%1」；請選擇以下其中之一：%2。</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>The %1 translation was not found in %2.</source>
        <translation>在 %2 中找不到 %1 翻譯。</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::LineDatabaseDialog</name>
    <message>
        <location filename="../ui/station/line_database_dialog.cpp" line="+91"/>
        <source>Line database</source>
        <translation>產線資料庫</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Every module this station tests is stored in its own database first (results.sqlite in the report folder); with a line database set, the station also sends each result there, and keeps it until the server has it.</source>
        <translation>本測試臺測試的每個模組都會先存入自己的資料庫（報告資料夾中的 results.sqlite）；設定產線資料庫後，測試臺還會把每個結果傳送到那裡，並在伺服器收到之前一直保留。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Server:</source>
        <translation>伺服器：</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The line&apos;s PostgreSQL database: postgresql://user@host[:port]/database. Empty: none. A password typed here (user:password@host) is stored with the station&apos;s settings as typed; put it into ~/.pgpass instead, which PostgreSQL reads by itself.</source>
        <translation>產線的 PostgreSQL 資料庫：postgresql://使用者@主機[:連接埠]/資料庫。留空：不使用。在此輸入的密碼（使用者:密碼@主機）會原樣儲存在測試臺的設定中；請改寫入 ~/.pgpass，PostgreSQL 會自行讀取。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Shared artifact folder:</source>
        <translation>共用附件資料夾：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A folder every station and the office can reach (a network share): each module&apos;s PDF report and recording are copied there, checked against their SHA-256, and the line database records that copy. Empty: the files stay on this station.</source>
        <translation>每個測試臺和辦公室都能存取的資料夾（網路共用）：每個模組的 PDF 報告和錄製檔會複製到這裡，並以 SHA-256 核對，產線資料庫記錄這份副本。留空：檔案只保留在本測試臺。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Browse…</source>
        <translation>瀏覽…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Test connection</source>
        <translation>測試連線</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Connect to the server now, as the station will (a fresh database gets ImuDesk&apos;s tables)</source>
        <translation>現在依測試臺的方式連線到伺服器（全新的資料庫會建立 ImuDesk 的資料表）</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>A line database is a PostgreSQL server: its address starts with postgresql://</source>
        <translation>產線資料庫是 PostgreSQL 伺服器：位址以 postgresql:// 開頭</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The password is stored with the station&apos;s settings as typed; ~/.pgpass keeps it out of them.</source>
        <translation>密碼會原樣儲存在測試臺的設定中；寫入 ~/.pgpass 可避免這一點。</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Shared artifact folder</source>
        <translation>共用附件資料夾</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Connecting to %1…</source>
        <translation>正在連線到 %1…</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Connected: schema %1</source>
        <translation>已連線：資料庫結構版本 %1</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::LineDatabaseStatus</name>
    <message>
        <location line="+33"/>
        <source> · connecting to the line database…</source>
        <translation> · 正在連線到產線資料庫…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source> · upload failing: %1</source>
        <translation> · 上傳失敗：%1</translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source> · %n result(s) waiting to upload</source>
        <translation>
            <numerusform> · %n 筆結果等待上傳</numerusform>
        </translation>
    </message>
    <message>
        <location line="+1"/>
        <source> · every result uploaded</source>
        <translation> · 所有結果皆已上傳</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Uploading to %1 fails: %2
The results wait in this station&apos;s database and go as soon as the server answers; nothing is lost.</source>
        <translation>上傳到 %1 失敗：%2
結果暫存在本測試臺的資料庫中，伺服器一有回應就會傳送；不會遺失任何資料。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Results go to the line database %1.</source>
        <translation>結果會傳送到產線資料庫 %1。</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::LiveBridgeDialog</name>
    <message>
        <location filename="../ui/bridge/live_bridge_dialog.cpp" line="+150"/>
        <source>Live bridge</source>
        <translation>即時橋接</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Foxglove WebSocket (Foxglove, Lichtblick, PlotJuggler)</source>
        <translation>Foxglove WebSocket（Foxglove、Lichtblick、PlotJuggler）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Address:</source>
        <translation>位址(&amp;A)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>127.0.0.1 (this computer only)</source>
        <translation>127.0.0.1（僅本機）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>0.0.0.0 (every network of this computer)</source>
        <translation>0.0.0.0（本機的所有網路）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Where clients may connect from. Another address than 127.0.0.1 lets anyone on that network read the data: the Foxglove protocol has no password.</source>
        <translation>用戶端可從何處連線。127.0.0.1 以外的位址允許該網路上的任何人讀取資料：Foxglove 協定沒有密碼。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Port:</source>
        <translation>連接埠(&amp;P)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>TCP port of the WebSocket server (Foxglove&apos;s usual port: 8765)</source>
        <translation>WebSocket 伺服器的 TCP 連接埠（Foxglove 常用連接埠：8765）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Foxglove and Lichtblick: Open connection &gt; Foxglove WebSocket, ws://127.0.0.1:%1. PlotJuggler: Streaming &gt; Foxglove Bridge. Each device&apos;s topics are /imu/&lt;serial&gt;/imu, mag, euler, status, ... as in an MCAP recording.</source>
        <translation>Foxglove 與 Lichtblick：Open connection &gt; Foxglove WebSocket，ws://127.0.0.1:%1。PlotJuggler：Streaming &gt; Foxglove Bridge。每台裝置的主題為 /imu/&lt;序號&gt;/imu、mag、euler、status 等，與 MCAP 記錄相同。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>PlotJuggler UDP (JSON)</source>
        <translation>PlotJuggler UDP（JSON）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Host:</source>
        <translation>主機(&amp;H)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Computer running PlotJuggler&apos;s UDP server (Streaming &gt; UDP Server, message protocol JSON, time stamp from the field &quot;timestamp&quot;)</source>
        <translation>執行 PlotJuggler UDP 伺服器的電腦（Streaming &gt; UDP Server，訊息協定 JSON，時間戳記取自欄位 &quot;timestamp&quot;）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>P&amp;ort:</source>
        <translation>連接埠(&amp;O)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>UDP port PlotJuggler listens on (its default: 9870)</source>
        <translation>PlotJuggler 監聽的 UDP 連接埠（預設：9870）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Log (clients, refused requests, dropped messages):</source>
        <translation>記錄(&amp;L)（用戶端、被拒絕的請求、捨棄的訊息）：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Close</source>
        <translation>關閉</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Warning: %1 is not this computer only. Anyone who can reach it on the network can read the devices&apos; data: the protocol has no password.</source>
        <translation>警告：%1 不僅限本機。網路上能存取它的任何人都可以讀取裝置資料：此協定沒有密碼。</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&amp;Stop</source>
        <translation>停止(&amp;S)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>&amp;Start</source>
        <translation>開始(&amp;S)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stop the bridge (Ctrl+Shift+B opens this window)</source>
        <translation>停止橋接（Ctrl+Shift+B 開啟此視窗）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Send the connected devices&apos; samples from now on</source>
        <translation>從現在起傳送已連線裝置的取樣</translation>
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
%2 台裝置；取樣：%3，遺漏：%4</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Choose the Foxglove WebSocket server, PlotJuggler UDP or both.</source>
        <translation>請選擇 Foxglove WebSocket 伺服器、PlotJuggler UDP 或兩者。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&apos;%1&apos; is not an IP address. Use 127.0.0.1 for this computer only or 0.0.0.0 for every network.</source>
        <translation>「%1」不是 IP 位址。僅本機請用 127.0.0.1，所有網路請用 0.0.0.0。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&apos;%1&apos; is not an IP address: give the address of the computer running PlotJuggler, e.g. 127.0.0.1.</source>
        <translation>「%1」不是 IP 位址：請填寫執行 PlotJuggler 的電腦位址，例如 127.0.0.1。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1
Choose another port, or close the program that uses this one.</source>
        <translation>%1
請選擇其他連接埠，或關閉佔用此連接埠的程式。</translation>
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
        <translation>無界</translation>
    </message>
    <message>
        <location line="+61"/>
        <source>Magnetometer calibration</source>
        <translation>地磁校準</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Before you start</source>
        <translation>開始之前</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Calibrate the magnetometer when you use the 9-axis (AHRS) mode, where the heading follows magnetic north. Without a magnetometer calibration, or where the field is disturbed, use the 6-axis mode instead.

Best: outdoors in an open space, more than 5 m from buildings and vehicles. Acceptable: indoors, more than 30 cm from iron furniture, monitors, motors, transformers, chargers and phones.

If the module is mounted on a PCB, in a housing or on a robot, calibrate it together with them, as one rigid body: calibrating the module alone does not help once it is mounted.</source>
        <translation>使用 9 軸（AHRS）模式時請進行地磁校準，此模式下航向角以磁北為基準。未進行地磁校準或磁場受干擾時，請改用 6 軸模式。

最佳：戶外空曠處，距建築物和車輛 5 m 以上。可接受：室內，距鐵製家具、顯示器、馬達、變壓器、充電器和手機 30 cm 以上。

若模組安裝在 PCB 上、外殼內或機器人上，請將它們作為一個剛體一起校準：模組安裝後，單獨校準模組並無幫助。</translation>
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
        <translation>校準需要 9 軸（AHRS）模式，即 CONFIG ATT MODE 1（出廠設定）。ImuDesk 先讀取模組的模式，僅當其執行於 6 軸模式時才提供切換；切換會傳送 CONFIG ATT MODE 1、SAVECONFIG 和 REBOOT。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Switch to 9-axis mode</source>
        <translation>切換到 9 軸模式</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>The module did not take ATT MODE 1 (%1). Check the connection and try again.</source>
        <translation>模組未接受 ATT MODE 1（%1）。請檢查連線後重試。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>read back differs</source>
        <translation>回讀值不一致</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>ATT MODE 1 set; saving it (SAVECONFIG)…</source>
        <translation>已設定 ATT MODE 1；正在儲存（SAVECONFIG）…</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1 failed: %2. Try again, or save and restart from the Configuration panel.</source>
        <translation>%1 失敗：%2。請重試，或在設定面板中儲存並重新啟動。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Saved; restarting the module (REBOOT)…</source>
        <translation>已儲存；正在重新啟動模組（REBOOT）…</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The module restarts in the 9-axis mode; reading it back…</source>
        <translation>模組以 9 軸模式重新啟動；正在回讀…</translation>
    </message>
    <message>
        <location line="+9"/>
        <location line="+195"/>
        <source>Environment check</source>
        <translation>環境檢查</translation>
    </message>
    <message>
        <location line="-194"/>
        <source>At the calibration spot, turn the module slowly through many orientations. The module&apos;s own iron is taken out of the field first; what is left must be the Earth&apos;s field (20-65 µT), the same in every orientation (within 10 µT), and steady while the module is still.</source>
        <translation>在校準位置把模組緩慢轉過多個朝向。先從磁場中去除模組自身的鐵磁干擾；剩下的必須是地磁場（20-65 µT），在各朝向上相同（相差不超過 10 µT），並且在模組靜止時保持穩定。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Raw |B|: the field strength as measured, the module&apos;s own iron included. Field at the spot: the strength once that iron is fitted out. Spread: how much it differs between orientations (5th to 95th percentile). Change while still: |B| drift while the gyro shows no turn.</source>
        <translation>原始 |B|：測得的磁場強度，包含模組自身的鐵磁干擾。此處磁場：擬合去除該干擾後的強度。離散：各朝向之間的差異（第 5 到第 95 百分位）。靜止時變化：陀螺儀顯示未轉動時 |B| 的漂移。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The raw field as it comes from the module (µT), one dot per sample</source>
        <translation>模組輸出的原始磁場（µT），每個樣本一個點</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Coverage: share of the 80 sphere cells the field direction has pointed into, with the module&apos;s own iron fitted out by the live fit (before a usable fit: the raw directions). The sphere, its readout and the verdict give this one figure. Largest gap: radius of the biggest uncovered area. Raw |B|: the field strength before calibration (its spread is the iron the fit removes). Fit: the field and the residual of ImuDesk&apos;s fit on the samples so far, refreshed every second. Samples: every sample taken for ImuDesk&apos;s fit (the sphere draws a thinned share of them).</source>
        <translation>覆蓋率：磁場方向已指向的 80 個球面單元所占比例，模組自身的鐵磁已由即時擬合去除（尚無可用擬合時：原始方向）。球面、其讀數和結論給出的是同一個數值。最大空缺：最大未覆蓋區域的半徑。原始 |B|：校準前的磁場強度（其波動即擬合要去除的鐵磁）。擬合：ImuDesk 對目前樣本擬合的磁場和殘差，每秒更新。樣本：為 ImuDesk 擬合採集的全部樣本（球面只繪製其中抽稀的一部分）。</translation>
    </message>
    <message>
        <location line="+56"/>
        <source>Place the module level (roll and pitch within 15 deg) and turn it slowly one full turn (360 deg). The heading must change continuously, without jumps of more than 10 deg; within +-5 deg of the true directions is acceptable. Turns made while the module is tilted or the field is disturbed are not judged: the check says so.</source>
        <translation>將模組水平放置（橫滾和俯仰在 15° 以內），緩慢轉動一整圈（360°）。航向必須連續變化，跳變不得超過 10°；與真實方向相差 ±5° 以內即可接受。模組傾斜或磁場受擾時的轉動不作判定：檢查會給出提示。</translation>
    </message>
    <message>
        <location line="+117"/>
        <source>read from the module; a switch to 9-axis is offered when needed</source>
        <translation>從模組讀取；需要時提供切換到 9 軸模式</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>turn the module at the spot: the field is judged with its own iron taken out</source>
        <translation>在該位置轉動模組：去除其自身鐵磁干擾後判斷磁場</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>slowly about every axis until the sphere is covered, usually 30-60 s; %1</source>
        <translation>繞每個軸緩慢轉動直到覆蓋整個球面，通常 30-60 s；%1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the module calibrates itself at the same time (CONFIG MCAL, firmware %1)</source>
        <translation>模組同時進行自身的校準（CONFIG MCAL，韌體 %1）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>firmware %1 calibrates in the background in 9-axis mode</source>
        <translation>韌體 %1 在 9 軸模式下於背景校準</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>ImuDesk&apos;s fit and the module&apos;s own verdict, side by side; saved with the samples</source>
        <translation>ImuDesk 的擬合與模組自身的結論並排顯示；與樣本一起保存</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>one level turn: the heading must follow without jumps</source>
        <translation>水平轉一圈：航向必須連續跟隨，沒有跳變</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>heading from the gyro alone: it drifts, the magnetometer is not used</source>
        <translation>航向僅來自陀螺儀：會漂移，不使用磁力計</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>heading follows magnetic north: needs this calibration</source>
        <translation>航向跟隨磁北：需要本校準</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>6-axis, for legged robots (firmware 1.7.x)</source>
        <translation>6 軸，用於足式機器人（韌體 1.7.x）</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>◀ the module</source>
        <translation>◀ 本模組</translation>
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
        <translation>當前原始 |B|</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>µT</source>
        <translation>µT</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Field at the spot</source>
        <translation>此處磁場</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>µT (Earth: 20–65)</source>
        <translation>µT（地磁場：20–65）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Module&apos;s own iron</source>
        <translation>模組自身鐵磁干擾</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>µT, removed by the calibration</source>
        <translation>µT，由校準去除</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Spread</source>
        <translation>離散</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>µT between orientations (≤ 10)</source>
        <translation>µT，各朝向之間（≤ 10）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Change while still</source>
        <translation>靜止時變化</translation>
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
        <translation>&lt;tr&gt;&lt;td&gt;預測航向誤差&lt;/td&gt;&lt;td align=right&gt;&lt;b&gt;%1°&lt;/b&gt;&lt;/td&gt;&lt;td&gt;水平模組，68 %；95 %：%2°&lt;/td&gt;&lt;/tr&gt;</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>&lt;tr&gt;&lt;td&gt;Coverage&lt;/td&gt;&lt;td align=right&gt;&lt;b&gt;%1 %&lt;/b&gt;&lt;/td&gt;&lt;td&gt;(%2 of %3 cells, the module&apos;s iron fitted out)&lt;/td&gt;&lt;/tr&gt;</source>
        <translation>&lt;tr&gt;&lt;td&gt;覆蓋率&lt;/td&gt;&lt;td align=right&gt;&lt;b&gt;%1 %&lt;/b&gt;&lt;/td&gt;&lt;td&gt;（%2/%3 個單元，已去除模組自身鐵磁）&lt;/td&gt;&lt;/tr&gt;</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&lt;tr&gt;&lt;td&gt;Coverage&lt;/td&gt;&lt;td align=right&gt;&lt;b&gt;%1 %&lt;/b&gt;&lt;/td&gt;&lt;td&gt;(%2 of %3 cells, raw directions: no usable fit yet)&lt;/td&gt;&lt;/tr&gt;</source>
        <translation>&lt;tr&gt;&lt;td&gt;覆蓋率&lt;/td&gt;&lt;td align=right&gt;&lt;b&gt;%1 %&lt;/b&gt;&lt;/td&gt;&lt;td&gt;（%2/%3 個單元，原始方向：尚無可用擬合）&lt;/td&gt;&lt;/tr&gt;</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>&lt;tr&gt;&lt;td&gt;Predicted heading error&lt;/td&gt;&lt;td align=right&gt;&lt;b&gt;%1°&lt;/b&gt;&lt;/td&gt;&lt;td&gt;level, 68 % (95 %: %4°; pass &amp;lt; %2°, refused &amp;gt; %3°)&lt;/td&gt;&lt;/tr&gt;</source>
        <translation>&lt;tr&gt;&lt;td&gt;預測航向誤差&lt;/td&gt;&lt;td align=right&gt;&lt;b&gt;%1°&lt;/b&gt;&lt;/td&gt;&lt;td&gt;水平，68 %（95 %：%4°；通過 &amp;lt; %2°，拒絕 &amp;gt; %3°）&lt;/td&gt;&lt;/tr&gt;</translation>
    </message>
    <message>
        <location line="+143"/>
        <source>The module&apos;s own calibration (MCAL) passed on the turns it collected, but its heading jumps in a level turn here: the field or the module&apos;s mounting changed since, or the collected turns did not represent this place.</source>
        <translation>模組自身的校準（MCAL）在其採集的轉動上通過了，但此處水平轉動時其航向跳變：之後磁場或模組安裝發生了變化，或採集的轉動不能代表此處。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>ImuDesk&apos;s fit passed on the collected samples, but the module computes its heading with its own calibration, which was not run to its end here: run the module&apos;s calibration (MCAL) too.</source>
        <translation>ImuDesk 的擬合在採集的樣本上通過了，但模組用自身的校準計算航向，而該校準此處未執行完畢：請同時執行模組的校準（MCAL）。</translation>
    </message>
    <message numerus="yes">
        <location line="+70"/>
        <source>The device now corrects its own output, so ImuDesk&apos;s fit keeps the %n raw sample(s) collected before.</source>
        <translation>
            <numerusform>裝置現在會自行校正其輸出，因此 ImuDesk 的擬合只保留此前擷取的 %n 個原始樣本。</numerusform>
        </translation>
    </message>
    <message>
        <location line="+32"/>
        <source>still running</source>
        <translation>仍在執行</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The device&apos;s own calibration (CONFIG MCAL START): %1. %2</source>
        <translation>裝置自身的校準（CONFIG MCAL START）：%1。%2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The device&apos;s own calibration (in the background): %1. %2</source>
        <translation>裝置自身的校準（背景）：%1。%2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Last reply: STAT=%1, PROGRESS=%2.</source>
        <translation>最後一次回應：STAT=%1，PROGRESS=%2。</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>The device&apos;s own calibration (MCAL) was not run; the verdict above is ImuDesk&apos;s fit alone.</source>
        <translation>未執行裝置自身的校準（MCAL）；上面的結論僅為 ImuDesk 的擬合。</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Hard iron: %1, %2, %3 µT
Field: %4 µT
Fit error: %5 %
Residual RMS: %6 µT
</source>
        <translation>硬鐵：%1, %2, %3 µT
磁場：%4 µT
擬合誤差：%5 %
殘差 RMS：%6 µT
</translation>
    </message>
    <message>
        <location line="-584"/>
        <location line="+179"/>
        <source>Turn the module</source>
        <translation>轉動模組</translation>
    </message>
    <message>
        <location line="-178"/>
        <source>Keep it in place and turn it slowly (20-100 deg/s) at least one full turn about each axis, until the sphere is green all over. Usually 30-60 s.</source>
        <translation>讓模組保持在原地，繞每個軸緩慢轉動（20-100 deg/s）至少一整圈，直到球面全部變綠。通常需要 30-60 s。</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Start the device&apos;s calibration</source>
        <translation>啟動裝置校準</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Fit ImuDesk&apos;s calibration now</source>
        <translation>立即以 ImuDesk 擬合校準</translation>
    </message>
    <message>
        <location line="+10"/>
        <location line="+155"/>
        <source>Result</source>
        <translation>結果</translation>
    </message>
    <message>
        <location line="-126"/>
        <location line="+127"/>
        <source>Heading check</source>
        <translation>航向角檢查</translation>
    </message>
    <message>
        <location line="+272"/>
        <location line="+16"/>
        <source>ImuDesk&apos;s fit: %1. %2</source>
        <translation>ImuDesk 擬合：%1。%2</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Device: STAT=%1 PROGRESS=%2
%3</source>
        <translation>裝置：STAT=%1 PROGRESS=%2
%3</translation>
    </message>
    <message>
        <location line="-385"/>
        <source>Reading the working mode from the module (LOG COMCONFIG)…</source>
        <translation>正在從模組讀取工作模式（LOG COMCONFIG）…</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>The working mode could not be read: %1. Check the connection, then press Back and Next to read it again, or switch to the 9-axis mode anyway.</source>
        <translation>無法讀取工作模式：%1。請檢查連線，然後按「上一步」和「下一步」重新讀取，或直接切換到 9 軸模式。</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>The module runs in the 9-axis (AHRS) mode, ATT MODE 1: nothing to change. Press Next.</source>
        <translation>模組執行於 9 軸（AHRS）模式，ATT MODE 1：無需變更。請按「下一步」。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The module runs in a 6-axis mode (ATT MODE %1): its heading ignores the magnetometer. Switch to the 9-axis mode before you calibrate.</source>
        <translation>模組執行於 6 軸模式（ATT MODE %1）：其航向不使用磁力計。校準前請切換到 9 軸模式。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>not reported</source>
        <translation>未回報</translation>
    </message>
    <message>
        <location line="+39"/>
        <source>So far: %1. %2</source>
        <translation>目前：%1。%2</translation>
    </message>
    <message>
        <location line="+83"/>
        <source>&lt;tr&gt;&lt;td&gt;ImuDesk&apos;s fit&lt;/td&gt;&lt;td align=right&gt;&lt;b&gt;%1&lt;/b&gt;&lt;/td&gt;&lt;td&gt;&lt;/td&gt;&lt;/tr&gt;</source>
        <translation>&lt;tr&gt;&lt;td&gt;ImuDesk 擬合&lt;/td&gt;&lt;td align=right&gt;&lt;b&gt;%1&lt;/b&gt;&lt;/td&gt;&lt;td&gt;&lt;/td&gt;&lt;/tr&gt;</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&lt;tr&gt;&lt;td&gt;Coverage&lt;/td&gt;&lt;td align=right&gt;&lt;b&gt;%1 %&lt;/b&gt;&lt;/td&gt;&lt;td&gt;of the field directions&lt;/td&gt;&lt;/tr&gt;</source>
        <translation>&lt;tr&gt;&lt;td&gt;覆蓋率&lt;/td&gt;&lt;td align=right&gt;&lt;b&gt;%1 %&lt;/b&gt;&lt;/td&gt;&lt;td&gt;磁場方向&lt;/td&gt;&lt;/tr&gt;</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>&lt;tr&gt;&lt;td&gt;Largest gap&lt;/td&gt;&lt;td align=right&gt;&lt;b&gt;%1°&lt;/b&gt;&lt;/td&gt;&lt;td&gt;radius&lt;/td&gt;&lt;/tr&gt;</source>
        <translation>&lt;tr&gt;&lt;td&gt;最大空缺&lt;/td&gt;&lt;td align=right&gt;&lt;b&gt;%1°&lt;/b&gt;&lt;/td&gt;&lt;td&gt;半徑&lt;/td&gt;&lt;/tr&gt;</translation>
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
        <translation>&lt;tr&gt;&lt;td&gt;擬合磁場&lt;/td&gt;&lt;td align=right&gt;&lt;b&gt;%1&lt;/b&gt;&lt;/td&gt;&lt;td&gt;µT&lt;/td&gt;&lt;/tr&gt;&lt;tr&gt;&lt;td&gt;擬合殘差&lt;/td&gt;&lt;td align=right&gt;&lt;b&gt;%2&lt;/b&gt;&lt;/td&gt;&lt;td&gt;µT RMS（%3 %）&lt;/td&gt;&lt;/tr&gt;</translation>
    </message>
    <message>
        <location line="-22"/>
        <location line="+34"/>
        <source>&lt;tr&gt;&lt;td&gt;Samples&lt;/td&gt;&lt;td align=right&gt;&lt;b&gt;%1&lt;/b&gt;&lt;/td&gt;&lt;td&gt;&lt;/td&gt;&lt;/tr&gt;</source>
        <translation>&lt;tr&gt;&lt;td&gt;樣本數&lt;/td&gt;&lt;td align=right&gt;&lt;b&gt;%1&lt;/b&gt;&lt;/td&gt;&lt;td&gt;&lt;/td&gt;&lt;/tr&gt;</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Setting ATT MODE 1…</source>
        <translation>正在設定 ATT MODE 1…</translation>
    </message>
    <message>
        <location line="+275"/>
        <source>No fit yet.</source>
        <translation>尚未擬合。</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>level module; pass below %1°, refused above %2°</source>
        <translation>水平放置；低於 %1° 通過，高於 %2° 拒絕</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>level module; a warning above %1°</source>
        <translation>水平放置；高於 %1° 給出警告</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Predicted heading error: %1° in 68 % of cases, %5° in 95 % (%2)
Hard-iron uncertainty: +-%3 µT
Soft-iron uncertainty: +-%4 %
</source>
        <translation>預測航向誤差：68 % 的情況下 %1°，95 % 的情況下 %5°（%2）
硬鐵不確定度：+-%3 µT
軟鐵不確定度：+-%4 %
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
        <translation>覆蓋率：%1 %
特徵值比：%2
樣本數：%3</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>What to check:</source>
        <translation>檢查事項：</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::MagSphereView</name>
    <message>
        <location filename="../ui/calibration/mag_sphere_view.cpp" line="+23"/>
        <source>Magnetometer samples on a sphere: cells turn green as the field directions cover them. Drag to turn the view, double-click to reset it.</source>
        <translation>球面上的磁力計樣本：磁場方向覆蓋到的格子會變綠。拖曳可旋轉檢視，按兩下可重設檢視。</translation>
    </message>
    <message>
        <location line="+88"/>
        <source>|B| %1 µT   coverage %2 %   %3 samples</source>
        <translation>|B| %1 µT   覆蓋率 %2 %   %3 個樣本</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1 samples, raw (no usable correction)</source>
        <translation>%1 個樣本，原始資料（無可用的校正）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 samples   coverage %2 %</source>
        <translation>%1 個樣本   覆蓋率 %2 %</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Predicted heading error %1°</source>
        <translation>預測航向誤差 %1°</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::MainWindow</name>
    <message>
        <location filename="../ui/workspace/main_window.cpp" line="+406"/>
        <source>Choose a port first.</source>
        <translation>請先選擇串列埠。</translation>
    </message>
    <message>
        <location line="+103"/>
        <source>ImuDesk</source>
        <translation>ImuDesk</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>About ImuDesk</source>
        <translation>關於 ImuDesk</translation>
    </message>
    <message>
        <location line="-152"/>
        <source>No device family simulates &quot;%1&quot;.</source>
        <translation>沒有裝置系列能模擬「%1」。</translation>
    </message>
    <message>
        <location line="+153"/>
        <source>&lt;h3&gt;ImuDesk %1&lt;/h3&gt;&lt;p&gt;A bench tool for IMU, AHRS and compass modules on serial, RS-485 Modbus and CAN links: live values and charts, settings, calibration, firmware updates, recordings and simulated devices.&lt;/p&gt;&lt;p&gt;Built with Qt %2.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;ImuDesk %1&lt;/h3&gt;&lt;p&gt;適用於序列埠、RS-485 Modbus 與 CAN 連線上的 IMU、AHRS 及羅盤模組的測試台工具：即時數值與曲線、設定、校準、韌體更新、記錄以及模擬裝置。&lt;/p&gt;&lt;p&gt;以 Qt %2 建置。&lt;/p&gt;</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>ImuDesk – IMU bench tool</source>
        <translation>ImuDesk – IMU 測試工具</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 – %2</source>
        <translation>%1 – %2</translation>
    </message>
    <message>
        <location line="+93"/>
        <source>%1, serial %2</source>
        <translation>%1，序號 %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 (tab %2)</source>
        <translation>%1（分頁 %2）</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>Save screenshot</source>
        <translation>儲存螢幕擷取畫面</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PNG images (*.png)</source>
        <translation>PNG 影像 (*.png)</translation>
    </message>
    <message>
        <location line="+149"/>
        <source>&amp;File</source>
        <translation>檔案(&amp;F)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Device</source>
        <translation>裝置(&amp;D)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;View</source>
        <translation>檢視(&amp;V)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Help</source>
        <translation>說明(&amp;H)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;New connection tab</source>
        <translation>新增連線分頁(&amp;N)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Open a tab for another device; each tab has its own connection and views</source>
        <translation>為另一台裝置開啟一個分頁；每個分頁都有獨立的連線和檢視</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Close tab</source>
        <translation>關閉分頁(&amp;C)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save &amp;screenshot…</source>
        <translation>儲存螢幕擷取畫面(&amp;S)…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Quit</source>
        <translation>結束(&amp;Q)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Connect</source>
        <translation>連線(&amp;C)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Connect to the port chosen in the connection bar</source>
        <translation>連線到連線列中所選的串列埠</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Disconnect</source>
        <translation>中斷連線(&amp;D)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Send LOG &amp;VERSION</source>
        <translation>傳送 LOG &amp;VERSION</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ask the device for its product name, firmware and serial number</source>
        <translation>查詢裝置的產品型號、韌體版本和序號</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Take one sample</source>
        <translation>採集一次資料(&amp;T)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Send LOG … ONMARK ONCE: the module outputs one frame of the type it sends, as a pulse on SYNC_IN would trigger</source>
        <translation>傳送 LOG … ONMARK ONCE：模組按其當前輸出類型輸出一幀資料，與 SYNC_IN 上的一個脈衝觸發效果相同</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;About ImuDesk</source>
        <translation>關於 ImuDesk(&amp;A)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Compare &amp;devices</source>
        <translation>裝置比較(&amp;D)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>One channel of every connected device on one time axis, live whichever tab is in front</source>
        <translation>所有已連接裝置的同一通道繪於同一時間軸上，無論哪個分頁在前都即時更新</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;User guide</source>
        <translation>使用者指南(&amp;U)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>How to connect, chart, configure, calibrate, update, record and test a tray</source>
        <translation>如何連接、繪圖、設定、校準、更新、錄製以及測試整盤模組</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Keyboard shortcuts</source>
        <translation>鍵盤快捷鍵(&amp;K)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Every key combination of this window, with what it does</source>
        <translation>本視窗的所有組合鍵及其功能</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Preferences…</source>
        <translation>偏好設定(&amp;P)…</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Layout: %1</source>
        <translation>版面配置：%1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Charts, the values table and the 3D attitude</source>
        <translation>圖表、數值表和 3D 姿態</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The device&apos;s settings beside the charts</source>
        <translation>裝置設定與圖表並列</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A large 3D attitude view and the console</source>
        <translation>大尺寸 3D 姿態檢視和主控台</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Charts, the values, the raw bytes and the command log</source>
        <translation>圖表、數值、原始位元組和命令記錄</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Production station…</source>
        <translation>生產測試臺(&amp;P)…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Test a tray of modules at once against a test plan: a verdict and a report per serial number</source>
        <translation>按測試計劃同時測試一托盤模組：每個序列號一個判定結果和一份報告</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Live bridge…</source>
        <translation>即時橋接(&amp;L)…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Send the connected devices&apos; samples live to Foxglove, Lichtblick and PlotJuggler</source>
        <translation>將已連線裝置的取樣即時傳送到 Foxglove、Lichtblick 與 PlotJuggler</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The live bridge is running: click to open its window</source>
        <translation>即時橋接正在執行：按一下開啟其視窗</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Results…</source>
        <translation>測試結果(&amp;R)…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Every module the station tested: search by serial number, each attempt&apos;s measurements, the yield and a measurement&apos;s trend with Cpk</source>
        <translation>測試臺測試過的每個模組：依序號搜尋、每次嘗試的量測項、良率，以及某一量測項的趨勢與 Cpk</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Reset layout</source>
        <translation>重設版面配置(&amp;R)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Put every panel of this tab back where the chosen layout has it</source>
        <translation>將此分頁的所有面板放回所選版面配置中的位置</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Compare devices</source>
        <translation>裝置比較</translation>
    </message>
    <message>
        <location line="-1"/>
        <source>Connection</source>
        <translation>連線</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::ModbusConnectDialog</name>
    <message>
        <location filename="../ui/bus/bus_connect_dialog.cpp" line="-207"/>
        <source>Connect over Modbus RTU</source>
        <translation>透過 Modbus RTU 連線</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The RS-485 adapter&apos;s serial port, or a simulated device</source>
        <translation>RS-485 轉接器的串列埠，或模擬裝置</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 (%2)</source>
        <translation>%1（%2）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Simulated HI14 (Modbus)</source>
        <translation>模擬 HI14（Modbus）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Simulated HEC495 (Modbus)</source>
        <translation>模擬 HEC495（Modbus）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Port:</source>
        <translation>串列埠(&amp;P)：</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>HiPNUC module</source>
        <translation>HiPNUC 模組</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>HEC495 compass</source>
        <translation>HEC495 羅盤</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Which register map the device has</source>
        <translation>裝置使用的暫存器表</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Device:</source>
        <translation>裝置(&amp;D)：</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Modbus node ID (slave address), 1 to 247; HiPNUC modules default to 80, the HEC495 to 1</source>
        <translation>Modbus 節點 ID（從站位址），1 至 247；HiPNUC 模組預設為 80，HEC495 預設為 1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Node ID:</source>
        <translation>節點 ID(&amp;N)：</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Baud rate of the RS-485 bus</source>
        <translation>RS-485 匯流排的波特率</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Baud rate:</source>
        <translation>波特率(&amp;B)：</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>None</source>
        <translation>無</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Even</source>
        <translation>偶同位</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Odd</source>
        <translation>奇同位</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>P&amp;arity:</source>
        <translation>同位檢查(&amp;A)：</translation>
    </message>
    <message>
        <location line="+4"/>
        <source> Hz</source>
        <translation> Hz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>How often the sensor registers are read; limited to what the baud rate carries</source>
        <translation>讀取感測器暫存器的頻率；受限於波特率可承載的資料量</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>P&amp;olling rate:</source>
        <translation>輪詢速率(&amp;O)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Also read the ship-motion registers (heave)</source>
        <translation>同時讀取船舶運動暫存器（垂蕩）</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::ModbusScanDialog</name>
    <message>
        <location filename="../ui/bus/modbus_scan_dialog.cpp" line="+24"/>
        <source>Scan the Modbus bus</source>
        <translation>掃描 Modbus 匯流排</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Every baud rate (4800 to 921600)</source>
        <translation>所有波特率（4800 至 921600）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>First node ID</source>
        <translation>起始節點 ID</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Last node ID</source>
        <translation>結束節點 ID</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Node ID</source>
        <translation>節點 ID</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Baud</source>
        <translation>波特率</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Device</source>
        <translation>裝置</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Start</source>
        <translation>開始</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cancel scan</source>
        <translation>取消掃描</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Use</source>
        <translation>使用</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Close</source>
        <translation>關閉</translation>
    </message>
    <message>
        <location line="+60"/>
        <source>The first node ID must not be above the last.</source>
        <translation>起始節點 ID 不得大於結束節點 ID。</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Scanning ...</source>
        <translation>正在掃描...</translation>
    </message>
    <message numerus="yes">
        <location line="+28"/>
        <source>Cancelled; %n device(s) found so far.</source>
        <translation>
            <numerusform>已取消；目前已找到 %n 台裝置。</numerusform>
        </translation>
    </message>
    <message>
        <location line="+2"/>
        <source>No device answered. Check the wiring (A/B), the baud rate and parity, or scan every baud rate.</source>
        <translation>沒有裝置回應。請檢查接線（A/B）、波特率和同位檢查，或掃描所有波特率。</translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>%n device(s) found.</source>
        <translation>
            <numerusform>已找到 %n 台裝置。</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>imudesk::ui::ModuleHistoryView</name>
    <message>
        <location filename="../ui/results/module_history_view.cpp" line="+125"/>
        <source>Attempt, step, measurement</source>
        <translation>嘗試、步驟、量測項</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Value</source>
        <translation>數值</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Unit</source>
        <translation>單位</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Limits</source>
        <translation>限值</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Marginal band</source>
        <translation>臨界區間</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Outcome</source>
        <translation>結果</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A pass whose value lies beyond this band, but inside its limits, is marked marginal</source>
        <translation>數值超出此範圍但仍在限值內的通過結果會標記為臨界</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Attempt</source>
        <translation>嘗試次數</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Kind</source>
        <translation>類型</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>File</source>
        <translation>檔案</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Files:</source>
        <translation>檔案：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Details:</source>
        <translation>詳細資訊：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Select an attempt, a step or a measurement to read all of it here.</source>
        <translation>選擇一次嘗試、一個步驟或一項量測，在此閱讀其全部內容。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Open</source>
        <translation>開啟</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Open the chosen file (the PDF report, the evidence recording) in the desktop&apos;s application for it</source>
        <translation>以桌面上的對應程式開啟所選檔案（PDF 報告、證據錄製檔）</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Select a module above to see every attempt of its serial number.</source>
        <translation>在上方選擇一個模組，即可檢視該序號的每一次嘗試。</translation>
    </message>
    <message numerus="yes">
        <location line="+4"/>
        <source>History of %1: %n attempt(s)</source>
        <translation>
            <numerusform>%1 的歷史：%n 次嘗試</numerusform>
        </translation>
    </message>
    <message>
        <location line="+36"/>
        <source>Attempt %1 · %2</source>
        <translation>第 %1 次嘗試 · %2</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Plan: %1
Station: %2 · slot %3 · operator %4
Product: %5 · firmware %6
Finished: %7
Record: %8</source>
        <translation>測試計劃：%1
測試臺：%2 · 工位 %3 · 作業員 %4
產品：%5 · 韌體 %6
結束：%7
記錄：%8</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>skipped</source>
        <translation>已略過</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>for information</source>
        <translation>僅供參考</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The value&apos;s magnitude is compared with the limit</source>
        <translation>以數值的絕對值與限值比較</translation>
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
        <translation>臨界區間：%1</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>PDF report</source>
        <translation>PDF 報告</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Recording</source>
        <translation>錄製檔</translation>
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
        <translation>開始時間</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Serial number</source>
        <translation>序號</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Outcome</source>
        <translation>結果</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Plan</source>
        <translation>測試計劃</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Station</source>
        <translation>測試臺</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Slot</source>
        <translation>工位</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Product</source>
        <translation>產品</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Firmware</source>
        <translation>韌體</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Attempt</source>
        <translation>嘗試次數</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::MountingPicker</name>
    <message>
        <location filename="../ui/configuration/mounting_picker.cpp" line="+34"/>
        <source>Mounting (URFR)</source>
        <translation>安裝方式（URFR）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Where do the module&apos;s axes point on the body (right, forward, up)? Pick a picture, a code, or the directions of IMU X and IMU Y. The setting takes effect after SAVECONFIG and a reset.</source>
        <translation>模組各軸在載體上指向哪個方向（右、前、上）？請選擇圖示、代碼，或指定 IMU X 與 IMU Y 的方向。此設定在 SAVECONFIG 並重設後生效。</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Code:</source>
        <translation>代碼：</translation>
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
        <translation>（無法構成右手座標系的安裝方式）</translation>
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
        <translation>未指定報告的檔名。</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>The report could not be rendered as PDF.</source>
        <translation>無法將報告生成為 PDF。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Cannot write the report to %1: %2. Choose another folder.</source>
        <translation>無法將報告寫入 %1：%2。請選擇其他資料夾。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Cannot write the report to %1: %2. Check the free disk space and try again.</source>
        <translation>無法將報告寫入 %1：%2。請檢查磁碟剩餘空間後重試。</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::PlanEditorDialog</name>
    <message>
        <location filename="../ui/station/plan_editor_dialog.cpp" line="+199"/>
        <source>Plan &amp;name:</source>
        <translation>計劃名稱(&amp;N)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Shown in the station window, the reports and the run folder&apos;s name</source>
        <translation>顯示在生產測試臺視窗、報告和執行資料夾名稱中</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Steps, in the order they run (unchecked: reported as skipped):</source>
        <translation>按執行順序排列的步驟（未勾選的記為已跳過）(&amp;S)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Up</source>
        <translation>上移</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Move the step up (Ctrl+Up)</source>
        <translation>上移該步驟（Ctrl+Up）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Down</source>
        <translation>下移</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Move the step down (Ctrl+Down)</source>
        <translation>將步驟下移（Ctrl+Down）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Add</source>
        <translation>新增</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Add a step after the selected one</source>
        <translation>在所選步驟之後新增步驟</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Remove</source>
        <translation>移除</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Remove the selected step (Delete)</source>
        <translation>移除所選步驟（Delete）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save</source>
        <translation>儲存</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Write the plan to its file (Ctrl+S)</source>
        <translation>將測試計劃寫入其檔案（Ctrl+S）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save as…</source>
        <translation>另存為…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Write the plan to another file; paths to its files follow it</source>
        <translation>將測試計劃寫入另一個檔案；其引用的檔案路徑隨之調整</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>The plan has changes that are not saved.</source>
        <translation>測試計劃有未儲存的更改。</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>%1. %2</source>
        <translation>%1. %2</translation>
    </message>
    <message>
        <location line="+52"/>
        <source>No step selected</source>
        <translation>未選擇步驟</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Choose a step in the list to edit its limits, or add one.</source>
        <translation>在列表中選擇一個步驟以編輯其限值，或新增一個步驟。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Step %1: %2</source>
        <translation>步驟 %1：%2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 This step is off: the reports list it as skipped.</source>
        <translation>%1 此步驟已禁用：報告中將其列為已跳過。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>This step has no parameters.</source>
        <translation>此步驟沒有參數。</translation>
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
範圍 %2%4 至 %3%4；預設 %5%4。</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>Marginal band</source>
        <translation>臨界區間</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Mark values close to the limit: they still pass, and the results say they were marginal</source>
        <translation>標記接近限值的數值：它們仍判為通過，但結果中註明為臨界</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Values above this, up to the limit, pass marked marginal.
From %1%3 to %2%3, below the limit.</source>
        <translation>高於此值且不超過限值的數值判為通過，並標記為臨界。
範圍 %1%3 至 %2%3，須低於限值。</translation>
    </message>
    <message>
        <location line="+46"/>
        <source>&quot;%1&quot; needs a number from %2 to %3</source>
        <translation>“%1”需要 %2 至 %3 之間的數值</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>step %1 (%2): %3</source>
        <translation>步驟 %1（%2）：%3</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>%1
Default: %2</source>
        <translation>%1
預設：%2</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Browse…</source>
        <translation>瀏覽…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Choose the file; inside the plan&apos;s folder it is kept relative to it</source>
        <translation>選擇檔案；位於測試計劃所在資料夾內的檔案以相對路徑儲存</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>Firmware images (*.hex *.ihex *.bin);;All files (*)</source>
        <translation>韌體映像 (*.hex *.ihex *.bin);;所有檔案 (*)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Configuration profiles (*.json);;All files (*)</source>
        <translation>配置方案 (*.json);;所有檔案 (*)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Choose a file for &quot;%1&quot;</source>
        <translation>為“%1”選擇檔案</translation>
    </message>
    <message>
        <location line="+63"/>
        <source>The plan can run.</source>
        <translation>測試計劃可以執行。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The plan cannot run yet:</source>
        <translation>測試計劃暫時無法執行：</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>(no name)</source>
        <translation>（未命名）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not saved</source>
        <translation>未儲存</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Test plan – %1 (%2)%3</source>
        <translation>測試計劃 – %1（%2）%3</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>Save test plan</source>
        <translation>儲存測試計劃</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Station plans (*.json)</source>
        <translation>測試計劃 (*.json)</translation>
    </message>
    <message>
        <location line="+43"/>
        <source>Test plan</source>
        <translation>測試計劃</translation>
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
        <translation>偏好設定</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Language</source>
        <translation>語言</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>System language</source>
        <translation>跟隨系統</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The language of the user interface. Takes effect the next time ImuDesk starts.</source>
        <translation>使用者介面的語言。下次啟動 ImuDesk 時生效。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Language:</source>
        <translation>語言(&amp;L)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The new language is used after a restart.</source>
        <translation>新語言在重新啟動後生效。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Display</source>
        <translation>顯示</translation>
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
        <translation>加速度計數值和曲線的單位。記錄的資料保持裝置的單位（G）。</translation>
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
        <translation>陀螺儀數值和曲線的單位。記錄的資料保持裝置的單位（deg/s）。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Angular &amp;rate:</source>
        <translation>角速度(&amp;R)：</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>ENU (east, north, up)</source>
        <translation>ENU（東、北、天）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>NED (north, east, down)</source>
        <translation>NED（北、東、地）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>World frame of the 3D attitude view.</source>
        <translation>三維姿態視圖的世界座標系。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Attitude &amp;frame:</source>
        <translation>姿態座標系(&amp;F)：</translation>
    </message>
    <message>
        <location line="+3"/>
        <source> Hz</source>
        <translation> Hz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>How often charts and values are redrawn (%1 to %2 Hz). Lower rates use less CPU.</source>
        <translation>曲線和數值的刷新頻率（%1 至 %2 Hz）。頻率越低佔用 CPU 越少。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Chart &amp;refresh:</source>
        <translation>曲線刷新(&amp;R)：</translation>
    </message>
    <message>
        <location line="+3"/>
        <source> min</source>
        <translation> 分鐘</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The longest time window a chart can show (%1 to %2 minutes).</source>
        <translation>曲線可顯示的最長時間視窗（%1 至 %2 分鐘）。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Chart &amp;history:</source>
        <translation>曲線歷史(&amp;H)：</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Recording</source>
        <translation>記錄</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Documents folder</source>
        <translation>文件資料夾</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Where new recordings are written.</source>
        <translation>新記錄儲存的位置。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Browse…</source>
        <translation>瀏覽(&amp;B)…</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Folder:</source>
        <translation>資料夾(&amp;F)：</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>File name of a new recording. {product}, {serial}, {date} and {time} are replaced.</source>
        <translation>新記錄的檔名。{product}、{serial}、{date} 和 {time} 會被替換。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>File &amp;pattern:</source>
        <translation>檔名模式(&amp;P)：</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Example:</source>
        <translation>範例：</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Connection</source>
        <translation>連線</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Reconnect by itself when an unplugged device comes back</source>
        <translation>拔出的裝置重新插入時自動重新連線(&amp;R)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>After a cable is pulled, wait for the same device (USB serial number, else port) and reconnect at the last baud rate.</source>
        <translation>線纜拔出後，等待同一裝置（按 USB 序號，否則按連接埠）重新出現，並以上次的波特率重新連線。</translation>
    </message>
    <message>
        <location line="+59"/>
        <source>Recording folder</source>
        <translation>記錄資料夾</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::ProfileDialog</name>
    <message>
        <location filename="../ui/configuration/profile_dialog.cpp" line="+21"/>
        <source>Configuration profiles</source>
        <translation>配置設定檔</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Read device</source>
        <translation>讀取裝置</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save device to profile…</source>
        <translation>將裝置配置存為設定檔…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Load profile…</source>
        <translation>載入設定檔…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Apply to this device</source>
        <translation>套用到此裝置</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Setting</source>
        <translation>設定項</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Profile</source>
        <translation>設定檔</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Device</source>
        <translation>裝置</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Note</source>
        <translation>備註</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Other ports (comma-separated):</source>
        <translation>其他串列埠（以逗號分隔）：</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Apply and save to each</source>
        <translation>逐一套用並儲存</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Port</source>
        <translation>串列埠</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Serial number</source>
        <translation>序號</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Product</source>
        <translation>產品</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Result</source>
        <translation>結果</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Details</source>
        <translation>詳細資訊</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>%1 settings applied and verified.</source>
        <translation>已套用並驗證 %1 項設定。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 of %2 settings verified. %3</source>
        <translation>已驗證 %1 / %2 項設定。%3</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>read the device first</source>
        <translation>請先讀取裝置</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Saved %1 settings to %2.</source>
        <translation>已將 %1 項設定儲存到 %2。</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Loaded %1 (%2 settings, taken from %3 %4).</source>
        <translation>已載入 %1（%2 項設定，取自 %3 %4）。</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>The device already matches the profile.</source>
        <translation>裝置已與設定檔一致。</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>OK (%1 changed)</source>
        <translation>OK（已變更 %1 項）</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>FAILED</source>
        <translation>失敗</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Save profile</source>
        <translation>儲存設定檔</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+8"/>
        <source>ImuDesk profiles (*.json)</source>
        <translation>ImuDesk 設定檔 (*.json)</translation>
    </message>
    <message>
        <location line="-1"/>
        <source>Load profile</source>
        <translation>載入設定檔</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::RawBytesView</name>
    <message numerus="yes">
        <location filename="../ui/workspace/raw_bytes_view.cpp" line="+196"/>
        <source>… %n read(s) or write(s) not shown (the log dropped them before this view caught up) …</source>
        <translation>
            <numerusform>… 有 %n 次讀取或寫入未顯示（在此檢視跟上之前，日誌已將其捨棄）…</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+3"/>
        <source>… %n byte(s) not shown (more arrived than the view holds) …</source>
        <translation>
            <numerusform>… 有 %n 位元組未顯示（到達的資料超出檢視容量）…</numerusform>
        </translation>
    </message>
    <message>
        <location line="+64"/>
        <source>Pause</source>
        <translation>暫停</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stop updating the view; the bytes are still recorded</source>
        <translation>停止更新檢視；位元組仍會繼續記錄</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Clear</source>
        <translation>清除</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Empty the view</source>
        <translation>清除檢視</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Copy</source>
        <translation>複製</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Copy the selected lines, or everything shown, to the clipboard</source>
        <translation>將所選行（未選取時為全部顯示內容）複製到剪貼簿</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Link traffic: time (s), direction (RX from the device, TX to it), byte offset, hex and ASCII</source>
        <translation>鏈路流量：時間（s）、方向（RX 為來自裝置，TX 為傳往裝置）、位元組偏移、十六進位和 ASCII</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>RX %1 bytes, TX %2 bytes</source>
        <translation>RX %1 位元組，TX %2 位元組</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Paused — %1</source>
        <translation>已暫停 — %1</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::RecordingControls</name>
    <message>
        <location filename="../ui/recording/recording_controls.cpp" line="+22"/>
        <source>Record</source>
        <translation>開始記錄</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Stop</source>
        <translation>停止</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Folder the capture files are written to</source>
        <translation>記錄檔寫入的資料夾</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>File name; {date}, {time}, {product} and {serial} are filled in. Ending in .imucap: every byte, to replay and export later; ending in .mcap: the decoded samples as MCAP, which PlotJuggler, Foxglove and Lichtblick open</source>
        <translation>檔名；{date}、{time}、{product} 與 {serial} 會自動填入。以 .imucap 結尾：記錄每個位元組，便於之後重播與匯出；以 .mcap 結尾：以 MCAP 記錄解碼後的取樣，可由 PlotJuggler、Foxglove 與 Lichtblick 開啟</translation>
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
        <translation>錄製到這麼多秒後自動停止（0：直到按下「停止」）</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>Folder:</source>
        <translation>資料夾：</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>File:</source>
        <translation>檔案：</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Stop after:</source>
        <translation>自動停止：</translation>
    </message>
    <message>
        <location line="+111"/>
        <source>Not recording: the device is not connected. Press Connect (Ctrl+K), then Record (Ctrl+R).</source>
        <translation>未在錄製：裝置未連線。請按「連線」(Ctrl+K)，再按「錄製」(Ctrl+R)。</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>The folder %1 does not exist. Choose another one.</source>
        <translation>資料夾 %1 不存在。請選擇其他資料夾。</translation>
    </message>
    <message>
        <location line="+47"/>
        <source>Recording to %1</source>
        <translation>正在記錄到 %1</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Saved %1 (stopped after %2 s, as set)</source>
        <translation>已儲存 %1（依設定在 %2 秒後停止）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Saved %1</source>
        <translation>已儲存 %1</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>%1:%2:%3</source>
        <translation>%1:%2:%3</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1 B</source>
        <translation>%1 位元組</translation>
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
            <numerusform>%n 幀</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>imudesk::ui::RegisterBrowser</name>
    <message>
        <location filename="../ui/bus/register_browser.cpp" line="+24"/>
        <source>Modbus registers</source>
        <translation>Modbus 暫存器</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>03 Read holding registers</source>
        <translation>03 讀取保持暫存器</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>06 Write single register</source>
        <translation>06 寫入單一暫存器</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Register address</source>
        <translation>暫存器位址</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Send</source>
        <translation>傳送</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Address</source>
        <translation>位址</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>Writing %1 to register 0x%2 ...</source>
        <translation>正在將 %1 寫入暫存器 0x%2...</translation>
    </message>
    <message>
        <location line="+90"/>
        <source>Not connected.</source>
        <translation>未連線。</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Only functions 03 and 06 are supported by these devices.</source>
        <translation>這些裝置僅支援功能碼 03 和 06。</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>count </source>
        <translation>數量 </translation>
    </message>
    <message>
        <location line="+3"/>
        <source>value </source>
        <translation>數值 </translation>
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
        <translation>最快速度</translation>
    </message>
    <message>
        <location line="-59"/>
        <source>Loop</source>
        <translation>循環播放</translation>
    </message>
    <message>
        <location line="+61"/>
        <source>Session: all devices together</source>
        <translation>工作階段：所有裝置同步</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>This capture is one device of a recorded session. Play, pause, seek, speed and loop act on every device of the session; the positions are times since the session started, so one position is the same instant in every tab.</source>
        <translation>此記錄是已錄製工作階段中的一台裝置。播放、暫停、定位、速度和循環作用於工作階段中的每台裝置；位置是自工作階段開始以來的時間，因此同一位置在每個分頁中都是同一時刻。</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>This file is a raw byte dump: it has no arrival times, so the times come from the device&apos;s own clock (HI91/HI83 time stamps or NMEA UTC time).</source>
        <translation>此檔案是原始位元組轉儲：沒有接收時間，因此時間取自裝置自身的時鐘（HI91/HI83 時間戳或 NMEA UTC 時間）。</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Pause</source>
        <translation>暫停</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1 / %2 (device clock)</source>
        <translation>%1 / %2（裝置時鐘）</translation>
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
        <translation>通過（臨界）</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>PASS</source>
        <translation>通過</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>FAIL</source>
        <translation>失敗</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>ERROR</source>
        <translation>錯誤</translation>
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
        <translation>測試結果</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Database:</source>
        <translation>資料庫：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Open…</source>
        <translation>開啟…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Read another results file (an SQLite file a station wrote: results.sqlite)</source>
        <translation>讀取另一個結果檔（測試臺寫入的 SQLite 檔案：results.sqlite）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Serial:</source>
        <translation>序號：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>part of a serial number</source>
        <translation>序號的一部分</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Modules whose serial number contains this text, as it is written</source>
        <translation>序號中包含此文字（依原樣比對）的模組</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Plan:</source>
        <translation>測試計劃：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Station:</source>
        <translation>測試臺：</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Any</source>
        <translation>全部</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>From</source>
        <translation>從</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Only modules started on this day or later (also for the yield and the trend)</source>
        <translation>僅包含在此日期或之後開始的模組（良率與趨勢也依此篩選）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>To</source>
        <translation>至</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Only modules started on this day or earlier (also for the trend)</source>
        <translation>僅包含在此日期或之前開始的模組（趨勢也依此篩選）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Search</source>
        <translation>搜尋</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>List the modules that match the filter, and count the yield of its plan (Enter)</source>
        <translation>列出符合篩選條件的模組，並統計其測試計劃的良率 (Enter)</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+95"/>
        <source>Reading the results database…</source>
        <translation>正在讀取結果資料庫…</translation>
    </message>
    <message>
        <location line="-94"/>
        <source>Modules</source>
        <translation>模組</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The modules found; select one to see every attempt of its serial number</source>
        <translation>找到的模組；選擇一個即可檢視該序號的每一次嘗試</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Yield</source>
        <translation>良率</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Pass, fail and yield of the chosen plan, per firmware and fixture slot</source>
        <translation>所選測試計劃的通過數、失敗數與良率，依韌體和治具工位統計</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Trend</source>
        <translation>趨勢</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>One measurement of the chosen plan over time, with its limits and Cpk</source>
        <translation>所選測試計劃中某一量測項隨時間的變化，含限值與 Cpk</translation>
    </message>
    <message>
        <location line="+5"/>
        <location line="+242"/>
        <source>Choose a plan in the filter above: the yield is counted per plan.</source>
        <translation>請在上方篩選列中選擇測試計劃：良率依測試計劃統計。</translation>
    </message>
    <message>
        <location line="-241"/>
        <location line="+261"/>
        <source>Choose a plan in the filter above to see its measurements over time.</source>
        <translation>請在上方篩選列中選擇測試計劃，以檢視其量測項隨時間的變化。</translation>
    </message>
    <message>
        <location line="-215"/>
        <source>Open a results database</source>
        <translation>開啟結果資料庫</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Results databases (*.sqlite *.db);;All files (*)</source>
        <translation>結果資料庫 (*.sqlite *.db);;所有檔案 (*)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>none</source>
        <translation>無</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the line database, %1</source>
        <translation>產線資料庫，%1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the file %1</source>
        <translation>檔案 %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>this station&apos;s database, %1</source>
        <translation>本測試臺的資料庫，%1</translation>
    </message>
    <message numerus="yes">
        <location line="+24"/>
        <source>The newest %n module(s) found; there are more: narrow the filter to see them.</source>
        <translation>
            <numerusform>顯示最新的 %n 個模組；還有更多：請縮小篩選範圍以檢視。</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+3"/>
        <source>%n module(s) found.</source>
        <translation>
            <numerusform>找到 %n 個模組。</numerusform>
        </translation>
    </message>
    <message>
        <location line="+14"/>
        <source>The line database %1 could not be read: %2
Check the network and that the server runs, then press Search to try again; or read this station&apos;s own file with Open….</source>
        <translation>無法讀取產線資料庫 %1：%2
請檢查網路以及伺服器是否在執行，然後按「搜尋」重試；或以「開啟…」讀取本測試臺自己的檔案。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 could not be read: %2
Is it a results database that ImuDesk wrote? Choose another file with Open….</source>
        <translation>無法讀取 %1：%2
它是 ImuDesk 寫入的結果資料庫嗎？請以「開啟…」選擇其他檔案。</translation>
    </message>
    <message>
        <location line="+72"/>
        <source>There are no results in %1 yet: the station writes this file with its first run. Open another file with Open…, or set the line database in the station window.</source>
        <translation>%1 中還沒有結果：測試臺在第一次執行時才會寫入此檔案。請以「開啟…」開啟其他檔案，或在測試臺視窗中設定產線資料庫。</translation>
    </message>
    <message>
        <location line="+43"/>
        <source>Reading the history of %1…</source>
        <translation>正在讀取 %1 的歷史…</translation>
    </message>
    <message>
        <location line="+58"/>
        <source>The plan&apos;s modules have no measurements here.</source>
        <translation>此測試計劃的模組在這裡沒有量測項。</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>%1 is not on this computer (it may be on the station that tested the module, or moved). Look for it in that station&apos;s report folder or in the shared artifact folder.</source>
        <translation>%1 不在這台電腦上（可能在測試該模組的測試臺上，或已被移動）。請在該測試臺的報告資料夾或共用附件資料夾中尋找。</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1 could not be opened: no application on this computer opens it. Open it from the file manager instead.</source>
        <translation>無法開啟 %1：這台電腦上沒有能開啟它的程式。請改從檔案總管中開啟。</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::RotationGuide</name>
    <message>
        <location filename="../ui/calibration/rotation_guide.cpp" line="+119"/>
        <source>Turn the module at least one full turn about each of its axes, slowly (20-100 deg/s), in any order</source>
        <translation>繞模組的每根軸至少轉一整圈，緩慢轉動（20-100 deg/s），順序不限</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>About X: roll it over</source>
        <translation>繞 X 軸：側向翻滾</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>About Y: tip it end over end</source>
        <translation>繞 Y 軸：首尾翻轉</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>About Z: turn it flat, like a compass</source>
        <translation>繞 Z 軸：平放旋轉，像指南針一樣</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::SessionRecordingWindow</name>
    <message>
        <location filename="../ui/recording/session_recording_window.cpp" line="+41"/>
        <source>Folder for the session</source>
        <translation>工作階段存放資料夾</translation>
    </message>
    <message>
        <location line="+49"/>
        <source>Exported the aligned session to %1.</source>
        <translation>已將對齊後的工作階段匯出到 %1。</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>Record all devices</source>
        <translation>錄製所有裝置</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Records every connected device into one session folder: each device&apos;s capture and session.json with their clocks. Replays and exports put the devices on one time base.</source>
        <translation>將所有已連線的裝置錄製到同一個工作階段資料夾：包括每台裝置的擷取檔，以及記錄各裝置時鐘的 session.json。重播與匯出時，所有裝置使用同一時間基準。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Into:</source>
        <translation>儲存到：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A new folder session-&lt;date&gt;-&lt;time&gt; is made here for each session</source>
        <translation>每個工作階段都會在此新建一個 session-&lt;date&gt;-&lt;time&gt; 資料夾</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Choose…</source>
        <translation>選擇…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Start</source>
        <translation>開始(&amp;S)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Start recording every connected device</source>
        <translation>開始錄製所有已連線的裝置</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>S&amp;top</source>
        <translation>停止(&amp;T)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Export aligned…</source>
        <translation>匯出對齊資料(&amp;E)…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The last session as one tidy CSV, every device&apos;s samples in the order of the common time</source>
        <translation>將最近一次工作階段匯出為單一整潔 CSV，所有裝置的樣本依共同時間排序</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>T&amp;wist to align…</source>
        <translation>扭轉對齊(&amp;W)…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Find each device&apos;s constant offset from sharp turns of a shared fixture</source>
        <translation>根據共用工裝的急速轉動，求出每台裝置的固定時間偏移</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Device</source>
        <translation>裝置</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Link</source>
        <translation>連線</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Bytes</source>
        <translation>位元組數</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Frames</source>
        <translation>幀數</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>State</source>
        <translation>狀態</translation>
    </message>
    <message>
        <location line="+46"/>
        <source>No connected device can be recorded: connect the devices in their tabs first.</source>
        <translation>沒有可錄製的已連線裝置：請先在各裝置的分頁中連線。</translation>
    </message>
    <message numerus="yes">
        <location line="+17"/>
        <source>Recording %n device(s) into %1…</source>
        <translation>
            <numerusform>正在將 %n 台裝置錄製到 %1…</numerusform>
        </translation>
    </message>
    <message>
        <location line="+34"/>
        <source>recording</source>
        <translation>錄製中</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>dropped out: %1</source>
        <translation>已斷線：%1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>back after a drop-out, recording</source>
        <translation>斷線後已恢復，錄製中</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>stopped: %1</source>
        <translation>已停止：%1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>dropped out (marked in the session)</source>
        <translation>已斷線（已在工作階段中標記）</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>complete</source>
        <translation>已完成</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Recording for %1 s into %2</source>
        <translation>正在錄製到 %2，已錄製 %1 s</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Session recorded in %1.</source>
        <translation>工作階段已錄製到 %1。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The recordings stopped, but the session&apos;s manifest could not be written: %1. The captures are in %2.</source>
        <translation>錄製已停止，但無法寫入工作階段清單檔：%1。擷取檔位於 %2。</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Exporting the session…</source>
        <translation>正在匯出工作階段…</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::SettingValueDelegate</name>
    <message>
        <location filename="../ui/configuration/setting_value_delegate.cpp" line="+83"/>
        <source>the value was refused</source>
        <translation>該數值被拒絕</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::ShortcutsDialog</name>
    <message>
        <location filename="../ui/workspace/help_dialogs.cpp" line="+233"/>
        <source>Keyboard shortcuts</source>
        <translation>鍵盤快捷鍵</translation>
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
        <translation>按鍵</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::StationModel</name>
    <message>
        <location filename="../ui/station/station_model.cpp" line="+79"/>
        <source>waiting to start</source>
        <translation>等待開始</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>connecting…</source>
        <translation>正在連線…</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>failed: %1</source>
        <translation>失敗：%1</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>failed</source>
        <translation>失敗</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>every step passed</source>
        <translation>所有步驟均通過</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not tested</source>
        <translation>未測試</translation>
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
        <translation>序列號 %1 · %2 · 韌體 %3</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+1"/>
        <source>(none)</source>
        <translation>（無）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Firmware after the update: %1</source>
        <translation>更新後的韌體：%1</translation>
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
        <translation>（臨界）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Report: %1</source>
        <translation>報告：%1</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1 (marginal)</source>
        <translation>%1（臨界）</translation>
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
        <translation>ImuDesk 生產測試報告：%1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Device</source>
        <translation>裝置</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Serial number</source>
        <translation>序列號</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Firmware</source>
        <translation>韌體</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1, updated to %2</source>
        <translation>%1，已更新為 %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Port</source>
        <translation>串列埠</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Plan</source>
        <translation>測試計劃</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>(unnamed)</source>
        <translation>（未命名）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Attempt</source>
        <translation>嘗試次數</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Started (UTC)</source>
        <translation>開始時間（UTC）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Finished (UTC)</source>
        <translation>結束時間（UTC）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Verdict:</source>
        <translation>結論：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 (marginal)</source>
        <translation>%1（臨界）</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Failed at %1</source>
        <translation>失敗步驟：%1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Steps</source>
        <translation>步驟</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Value</source>
        <translation>專案</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Measured</source>
        <translation>測量值</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Limit</source>
        <translation>限值</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Result</source>
        <translation>結果</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>within</source>
        <translation>在限值內</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>outside</source>
        <translation>超出限值</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>marginal</source>
        <translation>臨界</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Evidence recording: %1</source>
        <translation>證據記錄：%1</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>ImuDesk station report</source>
        <translation>ImuDesk 生產測試報告</translation>
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
        <translation>尚未識別</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>SN %1 · %2 · %3</source>
        <translation>序列號 %1 · %2 · %3</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>(none)</source>
        <translation>（無）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>(no product)</source>
        <translation>（無型號）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>(no firmware)</source>
        <translation>（無韌體版本）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 % of the plan, each step weighted by how long it takes</source>
        <translation>已完成測試計劃的 %1 %（各步驟按耗時加權）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Report</source>
        <translation>報告</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Open this module&apos;s PDF report: %1</source>
        <translation>開啟此模組的 PDF 報告：%1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Report of %1</source>
        <translation>%1 的報告</translation>
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
        <translation>生產測試臺</translation>
    </message>
    <message>
        <location line="-76"/>
        <source>Plan:</source>
        <translation>測試計劃：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Open…</source>
        <translation>開啟…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Open a test plan (a .json file saved by the plan editor)</source>
        <translation>開啟測試計劃（由計劃編輯器儲存的 .json 檔案）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Edit…</source>
        <translation>編輯…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Edit the plan&apos;s steps and limits; the next Start uses the saved plan</source>
        <translation>編輯測試計劃的步驟和限值；下次“開始”時使用已儲存的計劃</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>New from example</source>
        <translation>從示例新建</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A new plan from the example for HI14 modules, every step with its default limits, opened in the editor (without a firmware image; the profile step is off)</source>
        <translation>基於 HI14 模組示例新建測試計劃，各步驟使用預設限值，並在編輯器中開啟（不含韌體映像；配置方案步驟已禁用）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Ports:</source>
        <translation>串列埠：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The modules to test: check the port of each</source>
        <translation>要測試的模組：勾選每個模組的串列埠</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Refresh</source>
        <translation>重新整理</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Look for serial ports again (after plugging in an adapter)</source>
        <translation>重新查詢串列埠（插入介面卡後使用）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Simulated tray…</source>
        <translation>模擬托盤…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Start simulated HI14 modules on pseudo-terminals, some of them with faults, to try the station without hardware</source>
        <translation>在偽終端上啟動模擬 HI14 模組（部分帶有故障），無需硬體即可試用生產測試臺</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Reports:</source>
        <translation>報告：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Each run gets a folder here: the plan, summary.csv and summary.jsonl, a PDF report per module and the evidence recordings</source>
        <translation>每次執行都會在此處生成一個資料夾，內含：測試計劃、summary.csv 和 summary.jsonl、每個模組的 PDF 報告以及證據記錄</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Choose…</source>
        <translation>選擇…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Choose the folder for the run folders</source>
        <translation>選擇存放執行資料夾的資料夾</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Line database…</source>
        <translation>產線資料庫…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Send every result to the line&apos;s PostgreSQL database too, and copy the reports to a shared folder</source>
        <translation>同時把每個結果傳送到產線的 PostgreSQL 資料庫，並把報告複製到共用資料夾</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Start</source>
        <translation>開始</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Run the plan on every checked port at once (Ctrl+R)</source>
        <translation>在所有已勾選的串列埠上同時執行測試計劃（Ctrl+R）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stop every module&apos;s test; the running steps fail as cancelled (Esc)</source>
        <translation>停止所有模組的測試；執行中的步驟以“已取消”判為失敗（Esc）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Re-run failed</source>
        <translation>重測失敗模組</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Test the modules that failed again, into the same run folder as their next attempt (Ctrl+Shift+R)</source>
        <translation>重新測試失敗的模組，結果作為下一次嘗試存入同一執行資料夾（Ctrl+Shift+R）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Open run folder</source>
        <translation>開啟執行資料夾</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Open the folder of this run: the PDF reports, summary.csv, summary.jsonl and the evidence recordings (Ctrl+Shift+O)</source>
        <translation>開啟本次執行的資料夾：PDF 報告、summary.csv、summary.jsonl 與證據錄製檔 (Ctrl+Shift+O)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Choose a plan and check the ports of the modules, then press Start (Ctrl+R). Each module gets a tile here; click a tile to open that module&apos;s workspace.</source>
        <translation>選擇測試計劃並勾選模組的串列埠，然後按“開始”（Ctrl+R）。每個模組在此處顯示為一張卡片；點選卡片可開啟該模組的工作區。</translation>
    </message>
    <message>
        <location line="+7"/>
        <location line="+149"/>
        <source>%1 (simulated)</source>
        <translation>%1（模擬）</translation>
    </message>
    <message>
        <location line="-87"/>
        <source>No plan yet: open one, or start from the example</source>
        <translation>尚無測試計劃：請開啟一個，或從示例新建</translation>
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
        <translation>未儲存</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 · %2 of %3 steps · %4</source>
        <translation>%1 · 啟用 %2/%3 個步驟 · %4</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>(no name)</source>
        <translation>（未命名）</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Open test plan</source>
        <translation>開啟測試計劃</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Station plans (*.json);;All files (*)</source>
        <translation>測試計劃 (*.json);;所有檔案 (*)</translation>
    </message>
    <message>
        <location line="+53"/>
        <source>Made by %1</source>
        <translation>製造商：%1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Adapter serial number %1</source>
        <translation>介面卡序列號：%1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 (%2)</source>
        <translation>%1（%2）</translation>
    </message>
    <message>
        <location filename="../ui/station/station_view_tray.cpp" line="+37"/>
        <source>Simulated tray</source>
        <translation>模擬托盤</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Three with faults: a noisy gyro, a wrong mounting, firmware 1.6.6</source>
        <translation>其中三個帶故障：陀螺儀噪聲過大、安裝方向錯誤、韌體 1.6.6</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Simulated HI14 modules on pseudo-terminals, each on a rotation fixture (for the magnetometer calibration). They stop when this window closes.</source>
        <translation>執行在偽終端上的模擬 HI14 模組，每個都裝在旋轉工裝上（用於地磁校準）。關閉此視窗時它們隨之停止。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Modules:</source>
        <translation>模組數量：</translation>
    </message>
    <message>
        <location filename="../ui/station/station_view.cpp" line="+51"/>
        <source>Folder for the station&apos;s reports</source>
        <translation>生產測試臺的報告資料夾</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>A report could not be written:
%1</source>
        <translation>無法寫入報告：
%1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1 could not be opened: no application on this computer opens it. Open it from the file manager instead.</source>
        <translation>無法開啟 %1：這台電腦上沒有能開啟它的應用程式。請改從檔案總管開啟。</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>The report of %1 is written when its test has ended.</source>
        <translation>%1 的報告會在其測試結束後寫出。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 has no report: see the run folder&apos;s summary, or the message about the report.</source>
        <translation>%1 沒有報告：請查看執行資料夾中的摘要，或關於報告的提示訊息。</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>There is no run folder yet: press Start (Ctrl+R) first.</source>
        <translation>還沒有執行資料夾：請先按「開始」(Ctrl+R)。</translation>
    </message>
    <message>
        <location line="+59"/>
        <source>Reports of this run: %1</source>
        <translation>本次執行的報告：%1</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::StatusFlagsWidget</name>
    <message>
        <location filename="../ui/workspace/status_flags_widget.cpp" line="+114"/>
        <source>Status:</source>
        <translation>狀態：</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>good news when set</source>
        <translation>設定時表示良好</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>information</source>
        <translation>資訊</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>warning when set</source>
        <translation>設定時表示警告</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&lt;b&gt;%1&lt;/b&gt; (bit %2, %3): %4&lt;br&gt;&lt;i&gt;Source: %5&lt;/i&gt;</source>
        <translation>&lt;b&gt;%1&lt;/b&gt;（第 %2 位元，%3）：%4&lt;br&gt;&lt;i&gt;來源：%5&lt;/i&gt;</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>MAIN_STATUS flags of the latest frame. Set: amber = a warning about the data, blue = information, green = good news (magnetometer aiding the heading). Grey = clear; outlined = the frame carries no status word (firmware before 1.7.0, or another frame type)</source>
        <translation>最新訊框的 MAIN_STATUS 旗標。設定時：琥珀色 = 資料警告，藍色 = 資訊，綠色 = 良好（磁力計輔助航向）。灰色 = 未設定；僅外框 = 該訊框不含狀態字（1.7.0 之前的韌體或其他訊框類型）</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::ToolActions</name>
    <message>
        <location filename="../ui/workspace/tool_actions.cpp" line="+131"/>
        <source>&amp;Open capture…</source>
        <translation>開啟記錄檔(&amp;O)…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Play a recorded capture through the charts and views, as a live device (in a tab of its own when this one is connected); a recorded session&apos;s session.json opens every device, aligned</source>
        <translation>像即時裝置一樣在圖表與檢視中重播錄製的擷取（目前分頁已連線時在新分頁中開啟）；已錄製工作階段的 session.json 會開啟所有裝置並對齊</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Import vendor CSV…</source>
        <translation>匯入原廠 CSV(&amp;I)…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Turn a CSV written by the vendor&apos;s PC tool into a capture and play it</source>
        <translation>將原廠電腦工具產生的 CSV 轉換為記錄檔並重播</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Export capture…</source>
        <translation>匯出記錄檔(&amp;E)…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Write a capture as vendor CSV, tidy CSV or JSON Lines</source>
        <translation>將記錄檔匯出為原廠 CSV、整潔 CSV 或 JSON 逐行格式</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Analyze capture…</source>
        <translation>分析記錄檔(&amp;A)…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Statistics, output rate and jitter, lost frames and Allan deviation of a capture</source>
        <translation>記錄檔的統計值、輸出速率與抖動、遺失幀與艾倫變異</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Find devices…</source>
        <translation>尋找裝置(&amp;F)…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>One sweep of every serial port and CAN bus: what is connected, at what rate and address, and two devices at one address</source>
        <translation>一次掃描所有序列埠和 CAN 匯流排：連接了哪些裝置、速率和位址是多少，以及同一位址上的兩台裝置</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Connect over &amp;Modbus RTU…</source>
        <translation>透過 Modbus RTU 連線(&amp;M)…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Poll a module or compass on an RS-485 bus</source>
        <translation>輪詢 RS-485 匯流排上的模組或羅盤</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Connect over C&amp;AN…</source>
        <translation>透過 CAN 連線(&amp;A)…</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Find the node IDs that answer on the bus</source>
        <translation>找出匯流排上有回應的節點 ID</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Con&amp;figuration</source>
        <translation>配置(&amp;F)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Every setting of the connected module: read, edit, apply, save</source>
        <translation>已連線模組的所有設定：讀取、編輯、套用、儲存</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Profiles…</source>
        <translation>設定檔(&amp;P)…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save the configuration to a file, compare a file with the device, apply it to several</source>
        <translation>將配置儲存為檔案、比較檔案與裝置，或套用到多台裝置</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Output-rate &amp;calculator…</source>
        <translation>輸出速率計算器(&amp;C)…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Bytes per second of the chosen outputs against the link&apos;s capacity</source>
        <translation>所選輸出每秒的位元組數與鏈路容量的比較</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Update firmware…</source>
        <translation>更新韌體(&amp;U)…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Record</source>
        <translation>記錄(&amp;R)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Record this device to a capture file; the recording panel shows the progress and Stop</source>
        <translation>將此裝置錄製到擷取檔；錄製面板顯示進度與「停止」按鈕</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Record &amp;all devices…</source>
        <translation>錄製所有裝置(&amp;A)…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Record every connected tab into one session folder, the devices on one time base</source>
        <translation>將所有已連線的分頁錄製到同一個工作階段資料夾，所有裝置使用同一時間基準</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>T&amp;wist to align…</source>
        <translation>扭轉對齊(&amp;W)…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Align the devices of a recorded session from sharp turns of the fixture they share</source>
        <translation>根據共用工裝的急速轉動，對齊已錄製工作階段中的各裝置</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Magnetometer…</source>
        <translation>磁力計(&amp;M)…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Calibrate the magnetometer: turn the module while the sphere fills, then judge the fit</source>
        <translation>地磁校準：轉動模組直到球面填滿，然後評估擬合結果</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Gyro scale factor…</source>
        <translation>陀螺儀標度因數(&amp;G)…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Turn the module a known angle about Z to correct the gyro&apos;s scale (CONFIG USRCAL)</source>
        <translation>將模組繞 Z 軸轉動已知角度，以修正陀螺儀標度（CONFIG USRCAL）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Attitude reset / level…</source>
        <translation>姿態重設/調平(&amp;A)…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Zero the heading or level the module (ATT RST), after checking that it is still</source>
        <translation>確認模組靜止後，將航向角歸零或將模組調平（ATT RST）</translation>
    </message>
    <message>
        <location line="-22"/>
        <source>Listen to and configure a device on a CAN bus (J1939 or CANopen)</source>
        <translation>監聽並設定 CAN 匯流排上的裝置（J1939 或 CANopen）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Scan the bus…</source>
        <translation>掃描匯流排(&amp;S)…</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Write a new firmware image to the module over its serial port or its CAN bus, and verify it</source>
        <translation>透過序列埠或 CAN 匯流排向模組寫入新韌體並驗證</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>&amp;Verify module…</source>
        <translation>驗證模組(&amp;V)…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Is the module right? Turn it through still poses: its accelerometer, gyro and attitude judged, each figure with its bounds</source>
        <translation>模組是否正確？將它依次轉到各個靜止姿態：判定其加速度計、陀螺儀和姿態，每項數值都帶有信賴界限</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Compass calibration…</source>
        <translation>羅盤校準(&amp;C)…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The compass&apos;s own calibration methods, with the target poses to turn it to</source>
        <translation>羅盤本身的校準方法，並給出要轉到的目標姿態</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Calibration &amp;history…</source>
        <translation>校準歷史(&amp;H)…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Every finished calibration run per device: metrics, samples, PDF report</source>
        <translation>依裝置檢視每次完成的校準：指標、樣本、PDF 報告</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Tools</source>
        <translation>工具(&amp;T)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Calibrate</source>
        <translation>校準(&amp;C)</translation>
    </message>
    <message>
        <location line="+67"/>
        <source>%1: its capture %2 is missing.</source>
        <translation>%1：其記錄 %2 遺失。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 (%2): Modbus captures cannot be replayed yet; export the session to see its data.</source>
        <translation>%1（%2）：Modbus 記錄尚不能重播；請匯出工作階段以檢視其資料。</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The session opened without some of its devices:</source>
        <translation>工作階段已開啟，但缺少以下裝置：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>No device of the session could be replayed:</source>
        <translation>工作階段中沒有可重播的裝置：</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1 could not be imported: %2</source>
        <translation>無法匯入 %1：%2</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Open capture</source>
        <translation>開啟記錄檔</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+27"/>
        <source>Captures, sessions, vendor CSV and raw dumps (*.imucap session.json *.csv *.bin *.raw *.log *.dat *.txt);;All files (*)</source>
        <translation>記錄、工作階段、廠商 CSV 和原始資料 (*.imucap session.json *.csv *.bin *.raw *.log *.dat *.txt);;所有檔案 (*)</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Captures, vendor CSV and raw dumps (*.imucap *.csv *.bin *.raw *.log *.dat *.txt);;All files (*)</source>
        <translation>採集檔案、廠商 CSV 和原始轉儲 (*.imucap *.csv *.bin *.raw *.log *.dat *.txt);;所有檔案 (*)</translation>
    </message>
    <message>
        <location line="-31"/>
        <source>Import vendor CSV</source>
        <translation>匯入原廠 CSV</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CSV files (*.csv);;All files (*)</source>
        <translation>CSV 檔案 (*.csv);;所有檔案 (*)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Save the imported capture as</source>
        <translation>將匯入的記錄檔另存為</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Captures (*.imucap)</source>
        <translation>記錄檔 (*.imucap)</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Export capture</source>
        <translation>匯出記錄檔</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Analyze capture</source>
        <translation>分析記錄檔</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::TrendView</name>
    <message>
        <location filename="../ui/results/trend_view.cpp" line="+113"/>
        <source>Measurement:</source>
        <translation>量測項：</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Pass</source>
        <translation>通過</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Fail</source>
        <translation>失敗</translation>
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
        <translation>臨界區間</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Module started</source>
        <translation>模組開始測試時間</translation>
    </message>
    <message>
        <location line="+145"/>
        <source>No values of this measurement in the time chosen.</source>
        <translation>所選時間內沒有該量測項的數值。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>n = %1 · mean = %2 · σ = %3 · Cpk = %4</source>
        <translation>n = %1 · 平均值 = %2 · σ = %3 · Cpk = %4</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Cpk, the process capability index: how far the mean lies from the nearer limit, in units of three standard deviations: min(USL − mean, mean − LSL) / 3σ, against the latest module&apos;s limits (%1). 1.33 or more is commonly asked for; below 1, some modules will fail. &quot;–&quot;: no limit, or no spread (fewer than two values, or all equal).</source>
        <translation>Cpk（製程能力指數）：平均值距較近限值的距離，以三倍標準差為單位：min(USL − 平均值, 平均值 − LSL) / 3σ，依最新模組的限值（%1）計算。通常要求 1.33 以上；低於 1 時會有部分模組不合格。「–」：沒有限值，或沒有離散（少於兩個數值，或全部相等）。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>none</source>
        <translation>無</translation>
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
        <translation>扭轉對齊</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>For modules on one fixture. While every device records, turn the fixture sharply (faster than 60 deg/s) at least 3 times, at irregular intervals with a short rest between the turns, over at least 10 s. Then open the recorded session here: ImuDesk cross-correlates the devices&apos; gyro magnitudes and finds each device&apos;s constant time offset to the reference device.</source>
        <translation>適用於裝在同一工裝上的多個模組。在所有裝置錄製期間，急速轉動工裝（快於 60 deg/s）至少 3 次，間隔不規則，每兩次轉動之間短暫停頓，總時長至少 10 s。然後在此開啟錄製的工作階段：ImuDesk 會對各裝置的陀螺儀角速度大小做互相關，求出每台裝置相對於參考裝置的固定時間偏移。</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>The folder of a recorded session: the one with session.json and a capture per device</source>
        <translation>已錄製工作階段的資料夾：其中有 session.json，以及每台裝置各一個擷取檔</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Choose…</source>
        <translation>選擇…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Open another recorded session</source>
        <translation>開啟另一個已錄製的工作階段</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The device the others are aligned to: its offset is 0</source>
        <translation>其他裝置以此裝置為基準對齊：其偏移為 0</translation>
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
        <translation>扭轉時段的起點，即自錄製開始起算的秒數（0：從頭開始）</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>end</source>
        <translation>結尾</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>End of the twists, in seconds since the recording began (end: to the end of the session)</source>
        <translation>扭轉時段的終點，即自錄製開始起算的秒數（結尾：直到工作階段結束）</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Device</source>
        <translation>裝置</translation>
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
        <translation>相關係數</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Twists</source>
        <translation>扭轉次數</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Status</source>
        <translation>狀態</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Added to the device&apos;s times to put them on the reference&apos;s, in milliseconds</source>
        <translation>加到該裝置的時間上，使其與參考裝置的時間一致，單位為毫秒</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>One standard deviation of the offset, in milliseconds</source>
        <translation>偏移的一倍標準差，單位為毫秒</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Normalised correlation at the offset (-1 to 1); a good match is close to 1</source>
        <translation>該偏移處的正規化相關係數（-1 到 1）；匹配良好時接近 1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Sharp turns found in the device&apos;s gyro magnitude</source>
        <translation>在該裝置陀螺儀角速度大小中找到的急速轉動次數</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>Find offsets</source>
        <translation>計算偏移</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Read the captures and cross-correlate each device&apos;s gyro magnitude with the reference&apos;s</source>
        <translation>讀取擷取檔，將各裝置的陀螺儀角速度大小與參考裝置的做互相關</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Store offsets</source>
        <translation>儲存偏移</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Write the offsets found into the session&apos;s session.json; export and replay use them</source>
        <translation>將求得的偏移寫入此工作階段的 session.json；匯出與重播時會使用這些偏移</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>to</source>
        <translation>至</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Session:</source>
        <translation>工作階段：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Reference device:</source>
        <translation>參考裝置：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Twists from:</source>
        <translation>扭轉時段：</translation>
    </message>
    <message>
        <location line="+47"/>
        <location line="+167"/>
        <source>The session in %1 has one device only: twist to align needs two or more devices recorded together. Choose another session.</source>
        <translation>%1 中的工作階段只有一台裝置：扭轉對齊需要兩台以上一起錄製的裝置。請選擇其他工作階段。</translation>
    </message>
    <message>
        <location line="-164"/>
        <source>Press Find offsets to search the session&apos;s %1 devices for the twists.</source>
        <translation>請按「計算偏移」，在此工作階段的 %1 台裝置中尋找扭轉動作。</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>First device with gyroscope data</source>
        <translation>第一台有陀螺儀資料的裝置</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Choose the folder of a recorded session (the folder with session.json).</source>
        <translation>請選擇已錄製工作階段的資料夾（含有 session.json 的資料夾）。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 is not a folder. Choose the folder of a recorded session.</source>
        <translation>%1 不是資料夾。請選擇已錄製工作階段的資料夾。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 is not a recorded session: it has no session.json. Choose the folder a recording of several devices wrote.</source>
        <translation>%1 不是已錄製的工作階段：其中沒有 session.json。請選擇多裝置錄製所產生的資料夾。</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>The session in %1 cannot be read (%2). Choose another session folder.</source>
        <translation>無法讀取 %1 中的工作階段（%2）。請選擇其他工作階段資料夾。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The session in %1 lists no device. Choose another session folder.</source>
        <translation>%1 中的工作階段未列出任何裝置。請選擇其他工作階段資料夾。</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>Open a recorded session</source>
        <translation>開啟已錄製的工作階段</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Close</source>
        <translation>關閉</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stop the search; nothing is changed</source>
        <translation>停止搜尋；不做任何變更</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Close this window</source>
        <translation>關閉此視窗</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>stored earlier (%1)</source>
        <translation>先前已儲存（%1）</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>not searched yet</source>
        <translation>尚未搜尋</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>The end of the twists (%1 s) must be later than their start (%2 s); set To to end for the whole rest of the session.</source>
        <translation>扭轉時段的終點（%1 s）必須晚於起點（%2 s）；若要涵蓋工作階段的其餘全部，請將終點設為「結尾」。</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Reading the captures of %1 devices…</source>
        <translation>正在讀取 %1 台裝置的擷取檔…</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Widen From and To, or set them to 0 and end for the whole session.</source>
        <translation>請放寬扭轉時段的起點與終點，或將其設為 0 和「結尾」以涵蓋整個工作階段。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Search cancelled; nothing was changed.</source>
        <translation>搜尋已取消；未做任何變更。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>No device of the session has gyroscope data with a common time in the searched part. %1 Devices need gyroscope output (HI91) while recording.</source>
        <translation>此工作階段中沒有任何裝置在搜尋範圍內有帶共同時間的陀螺儀資料。%1 錄製時裝置須輸出陀螺儀資料（HI91）。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The reference %1 has no gyroscope data with a common time in the searched part. Choose another reference device. %2</source>
        <translation>參考裝置 %1 在搜尋範圍內沒有帶共同時間的陀螺儀資料。請選擇其他參考裝置。%2</translation>
    </message>
    <message>
        <location line="+57"/>
        <source>Aligned to %1: devices aligned %2 of %3. Check that the correlation is close to 1 and the ± column small, then press Store offsets.</source>
        <translation>已對齊到 %1：%3 台裝置中已對齊 %2 台。請確認相關係數接近 1、± 欄數值夠小，然後按「儲存偏移」。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>No device could be aligned to %1: see the Status column. Record the twists again (turn the fixture sharply at least 3 times at irregular intervals while every device records), or set From and To around the twists.</source>
        <translation>沒有裝置能對齊到 %1：請查看「狀態」欄。請重新錄製扭轉動作（在所有裝置錄製期間，以不規則的間隔急速轉動工裝至少 3 次），或將起點與終點設在扭轉動作的前後。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The captures of %1 could not be read: check that the session folder holds every file session.json names.</source>
        <translation>無法讀取 %1 的擷取檔：請確認工作階段資料夾中含有 session.json 列出的所有檔案。</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Capture unreadable: %1</source>
        <translation>擷取檔無法讀取：%1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>reference</source>
        <translation>參考裝置</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>No gyroscope data with a common time in the searched part; left as it was.</source>
        <translation>搜尋範圍內沒有帶共同時間的陀螺儀資料；維持原狀。</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>aligned</source>
        <translation>已對齊</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Not aligned: %1</source>
        <translation>未對齊：%1</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>The search is still running: wait for it to end, then store the offsets.</source>
        <translation>搜尋仍在進行中：請待其結束後再儲存偏移。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Nothing to store: no device is aligned. Press Find offsets first.</source>
        <translation>沒有可儲存的內容：沒有任何裝置已對齊。請先按「計算偏移」。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The session in %1 cannot be read any more (%2): nothing was stored. Check the folder, then find the offsets again.</source>
        <translation>已無法讀取 %1 中的工作階段（%2）：未儲存任何內容。請檢查該資料夾，然後重新計算偏移。</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The devices in %1 changed since the search: nothing was stored. Find the offsets again.</source>
        <translation>搜尋之後 %1 中的裝置已有變更：未儲存任何內容。請重新計算偏移。</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>The offsets could not be stored (%1). Check that the session folder is writable, then press Store offsets again.</source>
        <translation>無法儲存偏移（%1）。請確認工作階段資料夾可寫入，然後再按一次「儲存偏移」。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Offsets stored in %2 (devices aligned: %1); export and replay of the session use them.</source>
        <translation>偏移已儲存到 %2（已對齊裝置：%1 台）；匯出與重播此工作階段時會使用這些偏移。</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::UserGuideDialog</name>
    <message>
        <location filename="../ui/workspace/help_dialogs.cpp" line="-195"/>
        <source>The user guide is written in English; it is not available in your language yet. The menus and dialogs it describes are shown in your language.</source>
        <translation>使用者指南以英文撰寫，尚無您所用語言的版本。指南中描述的選單和對話框以您的語言顯示。</translation>
    </message>
    <message>
        <location line="+69"/>
        <source>ImuDesk user guide</source>
        <translation>ImuDesk 使用者指南</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Contents</source>
        <translation>目錄</translation>
    </message>
    <message>
        <location line="-37"/>
        <source>The user guide is not part of this build. It is docs/USER_GUIDE.md in ImuDesk&apos;s source.</source>
        <translation>此版本未包含使用者指南。它位於 ImuDesk 原始碼中的 docs/USER_GUIDE.md。</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::VerifyModuleWizard</name>
    <message>
        <location filename="../ui/calibration/verify_module_wizard.cpp" line="+47"/>
        <source>Verify module</source>
        <translation>驗證模組</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Turn the module through still poses</source>
        <translation>將模組依次轉到各個靜止姿態</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Press Start, then hold the module still for 3 s in each orientation below (every face up and down, then between them) and turn it to the next; the order does not matter. 9 poses are needed, 12 give the best figures. Keep it away from steel and magnets.</source>
        <translation>按「開始」，然後讓模組在下面每個朝向（每個面朝上和朝下，再加上它們之間的朝向）各保持靜止 3 s，再轉到下一個；順序不限。至少需要 9 個姿態，12 個可得到最好的結果。請遠離鋼鐵和磁鐵。</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>The bench&apos;s latitude (degrees, north positive): its normal gravity, WGS 84</source>
        <translation>測試台所在緯度（度，北緯為正）：用於計算 WGS 84 正常重力</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The bench&apos;s height above the ellipsoid (metres)</source>
        <translation>測試台的橢球高（公尺）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Measured gravity:</source>
        <translation>實測重力：</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The bench&apos;s gravity from a survey (m/s²), instead of latitude and height</source>
        <translation>測量得到的測試台重力值（m/s²），取代緯度和高度</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>height</source>
        <translation>高度</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Bench latitude:</source>
        <translation>測試台緯度：</translation>
    </message>
    <message>
        <location line="+13"/>
        <location line="+182"/>
        <source>Press Start.</source>
        <translation>請按「開始」。</translation>
    </message>
    <message>
        <location line="-172"/>
        <source>%v of 12 poses</source>
        <translation>%v / 12 個姿態</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Start</source>
        <translation>開始</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Start recording the poses (Ctrl+R)</source>
        <translation>開始記錄姿態（Ctrl+R）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stop</source>
        <translation>停止</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Result</source>
        <translation>結果</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Figure</source>
        <translation>項目</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Value</source>
        <translation>數值</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>95 % bound</source>
        <translation>95 % 界限</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Limits (pass / fail)</source>
        <translation>限值（通過 / 不合格）</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Verdict</source>
        <translation>判定</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Export report (PDF)…</source>
        <translation>匯出報告（PDF）…</translation>
    </message>
    <message>
        <location line="+86"/>
        <source>The recording is full (%1 samples): press Next.</source>
        <translation>記錄已滿（%1 個樣本）：請按「下一步」。</translation>
    </message>
    <message>
        <location line="+47"/>
        <source>Recorded: press Next for the result.</source>
        <translation>已記錄：按「下一步」查看結果。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stopped: press Start to record again, or Next to judge what was recorded.</source>
        <translation>已停止：按「開始」重新記錄，或按「下一步」判定已記錄的資料。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Turn the module to the next pose.</source>
        <translation>將模組轉到下一個姿態。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Hold still: %1 s</source>
        <translation>保持靜止：%1 s</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Pose recorded: turn to the next.</source>
        <translation>姿態已記錄：轉到下一個。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 distinct poses held (9 needed, 12 suggested); %2 s recorded, %3 samples.</source>
        <translation>已保持 %1 個不同姿態（至少 9 個，建議 12 個）；已記錄 %2 s，%3 個樣本。</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Nothing recorded yet: press Start and turn the module through the poses.</source>
        <translation>尚未記錄：請按「開始」並將模組依次轉到各個姿態。</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>Verdict: %1</source>
        <translation>判定：%1</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Accelerometer bias (mg; X, Y, Z)</source>
        <translation>加速度計零偏（mg；X、Y、Z）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Accelerometer scale error (%; X, Y, Z)</source>
        <translation>加速度計標度誤差（%；X、Y、Z）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Accelerometer misalignment, largest (°)</source>
        <translation>加速度計軸間失準，最大值（°）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Gyro bias (°/s; X, Y, Z)</source>
        <translation>陀螺儀零偏（°/s；X、Y、Z）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Gyro scale error (%; X, Y, Z)</source>
        <translation>陀螺儀標度誤差（%；X、Y、Z）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Gyro misalignment, largest (°)</source>
        <translation>陀螺儀軸間失準，最大值（°）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Roll error (°)</source>
        <translation>橫滾誤差（°）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Pitch error (°)</source>
        <translation>俯仰誤差（°）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Heading error (°)</source>
        <translation>航向誤差（°）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Attitude error while moving, RMS (°)</source>
        <translation>運動中的姿態誤差，RMS（°）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Attitude lag (ms)</source>
        <translation>姿態延遲（ms）</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>%1 still intervals, %2 distinct poses, gravity %3 m/s²</source>
        <translation>%1 個靜止區間，%2 個不同姿態，重力 %3 m/s²</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Verify module wizard</source>
        <translation>驗證模組精靈</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>Export report</source>
        <translation>匯出報告</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PDF (*.pdf)</source>
        <translation>PDF (*.pdf)</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Report written to %1</source>
        <translation>報告已寫入 %1</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::WindowHelpers</name>
    <message>
        <location filename="../ui/common/window_helpers.cpp" line="+31"/>
        <source>Could not save the screenshot to %1: %2</source>
        <translation>無法將截圖保存到 %1：%2</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::YieldView</name>
    <message>
        <location filename="../ui/results/yield_view.cpp" line="+54"/>
        <source>Modules</source>
        <translation>模組</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Pass</source>
        <translation>通過</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Fail</source>
        <translation>失敗</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Marginal</source>
        <translation>臨界</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Error</source>
        <translation>錯誤</translation>
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
        <translation>通過，但有數值超出臨界帶（同時計入通過數）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Pass / (pass + fail)</source>
        <translation>通過 / (通過 + 失敗)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>ERROR (the equipment failed: a port went away, a module did not answer) and ABORTED (the operator cancelled) are not counted in the yield: yield = pass / (pass + fail).</source>
        <translation>錯誤（設備故障：串列埠中斷、模組無回應）和中止（作業員取消）不計入良率：良率 = 通過 / (通過 + 失敗)。</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>Plan %1, since %2</source>
        <translation>測試計劃 %1，自 %2 起</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Plan %1, every module</source>
        <translation>測試計劃 %1，全部模組</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>All modules</source>
        <translation>全部模組</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Firmware %1</source>
        <translation>韌體 %1</translation>
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
        <translation>ImuDesk：HiPNUC IMU 模組測試工具。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>User interface language: zh_CN, zh_TW or en (default: the system&apos;s).</source>
        <translation>介面語言：zh_CN、zh_TW 或 en（預設跟隨系統）。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Start connected to a simulated device (model MODEL, default HI14) that streams HI91 at 100 Hz.</source>
        <translation>啟動後連線到一個以 100 Hz 輸出 HI91 的模擬裝置（型號 MODEL，預設 HI14）。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Firmware of the simulated device: 1.7.1 or 1.6.6 (default 1.7.1).</source>
        <translation>模擬裝置的韌體版本：1.7.1 或 1.6.6（預設 1.7.1）。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Motion of the simulated device: static, spin or tumble (default static).</source>
        <translation>模擬裝置的運動方式：static（靜止）、spin（旋轉）或 tumble（翻滾）（預設 static）。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Start connected to this serial port.</source>
        <translation>啟動後連線到此串列埠。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Baud rate for --port or --simulate (default: detect automatically).</source>
        <translation>--port 或 --simulate 使用的波特率（預設自動偵測）。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Start connected to a simulated HI14 (firmware 1.7.1) that tumbles slowly through every orientation.</source>
        <translation>啟動後連線到一個模擬 HI14（韌體 1.7.1），它會緩慢翻滾，經歷所有姿態。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Save the main window to this PNG file and quit (see --after).</source>
        <translation>將主視窗儲存為此 PNG 檔案後結束（參見 --after）。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Seconds to wait before --screenshot (default 3).</source>
        <translation>執行 --screenshot 前等待的秒數（預設 3）。</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Bring this panel to the front: configuration, recording, console, raw, commands, can (the CAN configuration) or sync (the clocks).</source>
        <translation>將此面板移到最前：configuration（配置）、recording（記錄）、console（主控台）、raw（原始位元組）、commands（指令日誌）、can（CAN 配置）或 sync（時鐘）。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Open Twist to align on a recorded session&apos;s FOLDER and find the devices&apos; offsets. With --screenshot the dialog is saved.</source>
        <translation>在已錄製工作階段的資料夾 FOLDER 上開啟「扭轉對齊」，並計算各裝置的偏移。與 --screenshot 同用時儲存該對話框。</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Start the live bridge (Tools &gt; Live bridge) on ADDR:PORT, e.g. 127.0.0.1:8765: the connected devices to Foxglove, Lichtblick and PlotJuggler.</source>
        <translation>在 ADDR:PORT（例如 127.0.0.1:8765）上啟動即時橋接（工具 &gt; 即時橋接）：將已連線的裝置傳送到 Foxglove、Lichtblick 與 PlotJuggler。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Open Device &gt; Find devices… at start (a first start without a device to open does so anyway).</source>
        <translation>啟動時開啟「裝置 &gt; 尋找裝置…」（首次啟動且沒有要開啟的裝置時也會自動開啟）。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Open Device &gt; Find devices… on a simulated bench (six devices on four ports and a virtualcan bus, two of them sharing a node ID) and sweep it.</source>
        <translation>在模擬測試台（四個連接埠和一條 virtualcan 匯流排上的六台裝置，其中兩台共用一個節點 ID）上開啟「裝置 &gt; 尋找裝置…」並進行掃描。</translation>
    </message>
    <message>
        <location line="+136"/>
        <source>Unknown panel &quot;%1&quot;; use configuration, recording, console, raw, commands, can or sync.</source>
        <translation>未知的面板「%1」；請使用 configuration、recording、console、raw、commands、can 或 sync。</translation>
    </message>
    <message>
        <location line="-156"/>
        <source>Open the production station window; with PLAN (a test plan file), load that plan. With --screenshot the station window is saved.</source>
        <translation>開啟生產測試臺視窗；指定 PLAN（測試計劃檔案）時載入該計劃。使用 --screenshot 時儲存的是生產測試臺視窗。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Open the production station with a simulated tray of 8 HI14 modules (one with a noisy gyro, one mounted wrongly, one with firmware 1.6.6) and run PLAN on it; without PLAN the built-in example plan, its firmware step without an image (the old module fails it) and its profile step off.</source>
        <translation>開啟生產測試臺，使用裝有 8 個 HI14 模組的模擬托盤（一個陀螺儀噪聲過大，一個安裝方向錯誤，一個韌體為 1.6.6），並在其上執行 PLAN；未指定 PLAN 時執行內建示例計劃，其韌體步驟不含映像（舊韌體模組在此步驟失敗），配置方案步驟禁用。</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>Test plan for --station or --station-demo.</source>
        <translation>--station 或 --station-demo 使用的測試計劃。</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Give either a model (--simulate) or a plan (--station), not both.</source>
        <translation>請指定型號（--simulate）或測試計劃（--station），二者不能同時指定。</translation>
    </message>
    <message>
        <location line="-13"/>
        <source>Model to simulate with --simulate (default HI14).</source>
        <translation>--simulate 模擬的型號（預設 HI14）。</translation>
    </message>
    <message>
        <location line="-42"/>
        <source>Start connected to another simulated device: hec495 (compass on serial), modbus (HI14 over Modbus RTU), can (HI14 J1939 on virtualcan) or canopen (HI14 CANopen on virtualcan); or replay a capture file, or a recorded session (its session.json or folder).</source>
        <translation>啟動時連線另一種模擬裝置：hec495（序列埠電子羅盤）、modbus（Modbus RTU 上的 HI14）、can（virtualcan 上的 HI14 J1939）或 canopen（virtualcan 上的 HI14 CANopen）；或重播一個記錄檔，或一個已錄製的工作階段（其 session.json 或資料夾）。</translation>
    </message>
    <message>
        <location line="+58"/>
        <source>A model name is only accepted after --simulate.</source>
        <translation>型號名稱只能接在 --simulate 之後。</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>--after needs a number of seconds from 0 to 3600.</source>
        <translation>--after 需要 0 到 3600 之間的秒數。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Use either --simulate or --port, not both.</source>
        <translation>--simulate 和 --port 只能擇一使用。</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Unsupported baud rate &quot;%1&quot;; use auto or one of: %2.</source>
        <translation>不支援的波特率「%1」；請使用 auto 或以下其中之一：%2。</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Invalid firmware version &quot;%1&quot;; use e.g. 1.7.1 or 1.6.6.</source>
        <translation>無效的韌體版本「%1」；請使用例如 1.7.1 或 1.6.6。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Unknown motion &quot;%1&quot;; use static, spin or tumble.</source>
        <translation>未知的運動方式「%1」；請使用 static、spin 或 tumble。</translation>
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
