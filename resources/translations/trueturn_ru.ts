<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="ru_RU">
<context>
    <name>tt::ui::AppState</name>
    <message>
        <source>Idle</source>
        <translation>Ожидание</translation>
    </message>
    <message>
        <source>Running</source>
        <translation>Выполняется</translation>
    </message>
    <message>
        <source>Paused</source>
        <translation>Пауза</translation>
    </message>
    <message>
        <source>Fault</source>
        <translation>Авария</translation>
    </message>
</context>
<context>
    <name>tt::ui::MainWindow</name>
    <message>
        <source>About TrueTurn</source>
        <translation>О программе TrueTurn</translation>
    </message>
    <message>
        <source>&lt;h2&gt;TrueTurn %1&lt;/h2&gt;&lt;p&gt;Adaptive accuracy control for lathes: run-to-run control of the shaft profile, in-process compensation of boring-bar deflection, feed scheduling and drive corrections.&lt;/p&gt;&lt;p&gt;Qt %2&lt;/p&gt;</source>
        <translation>&lt;h2&gt;TrueTurn %1&lt;/h2&gt;&lt;p&gt;Адаптивное управление точностью токарной обработки: управление профилем вала от детали к детали, компенсация прогиба расточной оправки в процессе обработки, программирование подач и коррекция приводов.&lt;/p&gt;&lt;p&gt;Qt %2&lt;/p&gt;</translation>
    </message>
    <message>
        <source>TrueTurn — adaptive lathe control</source>
        <translation>TrueTurn — адаптивное управление токарным станком</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Файл</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>В&amp;ыход</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Вид</translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation>&amp;Язык</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Справка</translation>
    </message>
    <message>
        <source>&amp;About TrueTurn</source>
        <translation>&amp;О программе TrueTurn</translation>
    </message>
    <message>
        <source>Loop: %1</source>
        <translation>Контур: %1</translation>
    </message>
    <message>
        <source>Loop: %1 — %2</source>
        <translation>Контур: %1 — %2</translation>
    </message>
    <message>
        <source>no devices connected</source>
        <translation>устройства не подключены</translation>
    </message>
    <message>
        <source>Devices: %1</source>
        <translation>Устройства: %1</translation>
    </message>
    <message>
        <source>ready</source>
        <translation>готовы</translation>
    </message>
    <message>
        <source>fault</source>
        <translation>авария</translation>
    </message>
    <message>
        <source>check</source>
        <translation>проверить</translation>
    </message>
    <message>
        <source>none</source>
        <translation>нет</translation>
    </message>
    <message>
        <source>History: %1</source>
        <translation>История: %1</translation>
    </message>
</context>
<context>
    <name>tt::ui::PlannedPage</name>
    <message>
        <source>Run</source>
        <translation>Работа</translation>
    </message>
    <message>
        <source>Measurements</source>
        <translation>Измерения</translation>
    </message>
    <message>
        <source>Tools</source>
        <translation>Инструменты</translation>
    </message>
    <message>
        <source>Calibration</source>
        <translation>Калибровка</translation>
    </message>
    <message>
        <source>Controller</source>
        <translation>Регулятор</translation>
    </message>
    <message>
        <source>Reports</source>
        <translation>Отчёты</translation>
    </message>
    <message>
        <source>Devices</source>
        <translation>Устройства</translation>
    </message>
    <message>
        <source>Settings</source>
        <translation>Настройки</translation>
    </message>
    <message>
        <source>Closed-loop run</source>
        <translation>Работа в замкнутом контуре</translation>
    </message>
    <message>
        <source>Start, pause and stop the run-to-run loop; the profile error of the last part against the tolerance band; the correction path; alarms.</source>
        <translation>Пуск, пауза и останов контура управления от детали к детали; погрешность профиля последней детали относительно поля допуска; траектория коррекции; тревоги.</translation>
    </message>
    <message>
        <source>No parts measured yet</source>
        <translation>Детали ещё не измерялись</translation>
    </message>
    <message>
        <source>Measured diameters of every part at the control points, accepted or rejected with the reason, and manual entry for a hand micrometer.</source>
        <translation>Измеренные диаметры каждой детали в контрольных точках, принятые или отклонённые с указанием причины, и ручной ввод с ручного микрометра.</translation>
    </message>
    <message>
        <source>Tool stiffness table</source>
        <translation>Таблица жёсткости инструмента</translation>
    </message>
    <message>
        <source>Boring bars and holders: section, overhang, material, computed and measured stiffness (N/mm), and the cross-feed current-to-force gain k&lt;sub&gt;p&lt;/sub&gt;.</source>
        <translation>Расточные оправки и державки: сечение, вылет, материал, расчётная и измеренная жёсткость (Н/мм) и коэффициент ток–сила k&lt;sub&gt;p&lt;/sub&gt; поперечной подачи.</translation>
    </message>
    <message>
        <source>Calibration wizards</source>
        <translation>Мастера калибровки</translation>
    </message>
    <message>
        <source>Probe-mandrel linearisation (ADC code to deflection table) and the current-to-force gain k&lt;sub&gt;p&lt;/sub&gt; from known loads.</source>
        <translation>Линеаризация оправки-датчика (таблица код АЦП → прогиб) и коэффициент ток–сила k&lt;sub&gt;p&lt;/sub&gt; по известным нагрузкам.</translation>
    </message>
    <message>
        <source>Controller tuning</source>
        <translation>Настройка регулятора</translation>
    </message>
    <message>
        <source>Transport delay z, weights R1 and R2, correction limits, the disturbance model and the resulting LQG gains.</source>
        <translation>Транспортное запаздывание z, веса R1 и R2, пределы коррекции, модель возмущений и полученные коэффициенты ЛКГ-регулятора.</translation>
    </message>
    <message>
        <source>No runs recorded yet</source>
        <translation>Записанных серий пока нет</translation>
    </message>
    <message>
        <source>Per-part profiles, SPC charts and capability (Cp, Cpk) at the control points, with PDF and CSV export.</source>
        <translation>Профили деталей, контрольные карты SPC и индексы воспроизводимости (Cp, Cpk) в контрольных точках с экспортом в PDF и CSV.</translation>
    </message>
    <message>
        <source>Gauge micrometer, probe mandrel, drive-current readout and the correction output to the CNC; the built-in simulator is always available.</source>
        <translation>Цифровой микрометр, оправка-датчик, считывание тока привода и вывод коррекции в ЧПУ; встроенный симулятор доступен всегда.</translation>
    </message>
</context>
<context>
    <name>tt::ui::SettingsPage</name>
    <message>
        <source>Terminal</source>
        <translation>Терминал</translation>
    </message>
    <message>
        <source>Language</source>
        <translation>Язык</translation>
    </message>
    <message>
        <source>Operator</source>
        <translation>Оператор</translation>
    </message>
    <message>
        <source>Name recorded with every change you apply</source>
        <translation>Имя, записываемое с каждым применённым изменением</translation>
    </message>
    <message>
        <source>Run history</source>
        <translation>История серий</translation>
    </message>
</context>
</TS>