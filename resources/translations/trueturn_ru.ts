<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="ru_RU">
<context>
    <name>BoringPanel</name>
    <message>
        <source>The drive current read-out is silent or disconnected.</source>
        <translation>Датчик тока привода не отвечает или отключён.</translation>
    </message>
    <message>
        <source>The probe mandrel is silent or disconnected.</source>
        <translation>Оправка-датчик не отвечает или отключена.</translation>
    </message>
    <message>
        <source>The probe mandrel sends raw codes without a linearisation table: load one on the Calibration page.</source>
        <translation>Оправка-датчик передаёт необработанные коды АЦП без таблицы линеаризации: загрузите таблицу на странице «Калибровка».</translation>
    </message>
    <message>
        <source>Taper or contour (or a feed move): the force cannot be read from the current here.</source>
        <translation>Конус или контур (или перемещение на подаче): здесь силу нельзя определить по току.</translation>
    </message>
    <message>
        <source>The cross slide does not move with the dither: it sticks, or the dither is off.</source>
        <translation>Поперечный суппорт не совершает колебательного движения: он заедает, или дизеринг выключен.</translation>
    </message>
    <message>
        <source>The dither stroke is too short for this PLC cycle: too few readings at constant speed. Use a longer dither period or a shorter PLC cycle.</source>
        <translation>Ход дизеринга слишком короткий для этого цикла ПЛК: мало отсчётов на постоянной скорости. Увеличьте период дизеринга или уменьшите цикл ПЛК.</translation>
    </message>
    <message>
        <source>Waiting for a forward and a reverse dither stroke.</source>
        <translation>Ожидание прямого и обратного хода дизеринга.</translation>
    </message>
    <message>
        <source>Holding the offset at %1 mm</source>
        <translation>Смещение удерживается: %1 мм</translation>
    </message>
    <message>
        <source>The CNC does not take the offset: %1</source>
        <translation>ЧПУ не принимает смещение: %1</translation>
    </message>
    <message>
        <source>Compensating</source>
        <translation>Компенсация</translation>
    </message>
    <message>
        <source>The offset is at its range limit: the deflection is larger than the limit allows.</source>
        <translation>Смещение на пределе: прогиб больше, чем допускает предел.</translation>
    </message>
    <message>
        <source>The offset moves at its rate limit.</source>
        <translation>Смещение изменяется с предельной скоростью.</translation>
    </message>
    <message>
        <source>The offset follows the measured deflection.</source>
        <translation>Смещение следует за измеренным прогибом.</translation>
    </message>
    <message>
        <source>No data from the probe mandrel for more than %1 ms.</source>
        <translation>От оправки-датчика нет данных более %1 мс.</translation>
    </message>
    <message>
        <source>No valid deflection this cycle.</source>
        <translation>В этом цикле нет достоверного прогиба.</translation>
    </message>
    <message>
        <source>The device reports: %1</source>
        <translation>Устройство сообщает: %1</translation>
    </message>
    <message>
        <source>ready</source>
        <translation>готов</translation>
    </message>
    <message>
        <source>not answering yet</source>
        <translation>пока не отвечает</translation>
    </message>
    <message>
        <source>disconnected</source>
        <translation>отключён</translation>
    </message>
    <message>
        <source>in error</source>
        <translation>в состоянии ошибки</translation>
    </message>
    <message>
        <source>The CNC output is %1.</source>
        <translation>Выход коррекции в ЧПУ: %1.</translation>
    </message>
    <message>
        <source>The CNC does not take the offset.</source>
        <translation>ЧПУ не принимает смещение.</translation>
    </message>
    <message>
        <source>The tool has no stiffness: enter its section and overhang on the Tools page.</source>
        <translation>У инструмента не задана жёсткость: введите его сечение и вылет на странице «Инструменты».</translation>
    </message>
    <message>
        <source>The tool has no current-to-force gain k_p: calibrate it on the Calibration page.</source>
        <translation>У инструмента нет коэффициента ток–сила k_p: откалибруйте его на странице «Калибровка».</translation>
    </message>
    <message>
        <source>The chosen source has no drive current read-out.</source>
        <translation>У выбранного источника нет датчика тока привода.</translation>
    </message>
    <message>
        <source>The chosen source has no probe mandrel.</source>
        <translation>У выбранного источника нет оправки-датчика.</translation>
    </message>
    <message>
        <source>Choose the mandrel&apos;s plane that lies along X.</source>
        <translation>Выберите плоскость оправки, лежащую вдоль X.</translation>
    </message>
    <message>
        <source>The offset limit of %1 mm is outside %2 to %3 mm.</source>
        <translation>Предел смещения %1 мм вне диапазона от %2 до %3 мм.</translation>
    </message>
    <message>
        <source>The rate limit of %1 mm/s is outside %2 to %3 mm/s.</source>
        <translation>Предел скорости %1 мм/с вне диапазона от %2 до %3 мм/с.</translation>
    </message>
    <message>
        <source>The PLC cycle of %1 ms is outside %2 to %3 ms.</source>
        <translation>Цикл ПЛК %1 мс вне диапазона от %2 до %3 мс.</translation>
    </message>
    <message>
        <source>The simulated station runs at a PLC cycle of %1 ms, not %2 ms.</source>
        <translation>Стенд-симулятор работает с циклом ПЛК %1 мс, а не %2 мс.</translation>
    </message>
    <message>
        <source>The force estimator&apos;s settings are refused.</source>
        <translation>Настройки оценки силы отклонены.</translation>
    </message>
    <message>
        <source>The CNC holds an offset of %1 mm, more than the limit of %2 mm: zero the offset first (tool out of the bore).</source>
        <translation>В ЧПУ установлено смещение %1 мм — больше предела %2 мм: сначала обнулите смещение (инструмент выведен из отверстия).</translation>
    </message>
    <message>
        <source>The run is refused.</source>
        <translation>Запуск отклонён.</translation>
    </message>
</context>
<context>
    <name>CornerPlots</name>
    <message>
        <source>Path near the corner</source>
        <translation>Траектория у угла</translation>
    </message>
    <message>
        <source>Z, mm</source>
        <translation>Z, мм</translation>
    </message>
    <message>
        <source>X, mm</source>
        <translation>X, мм</translation>
    </message>
    <message>
        <source>Programmed</source>
        <translation>Заданная</translation>
    </message>
    <message>
        <source>Without pulse</source>
        <translation>Без импульса</translation>
    </message>
    <message>
        <source>With pulse</source>
        <translation>С импульсом</translation>
    </message>
    <message>
        <source>Contour error</source>
        <translation>Траекторная ошибка</translation>
    </message>
    <message>
        <source>Time, ms</source>
        <translation>Время, мс</translation>
    </message>
    <message>
        <source>Error, µm</source>
        <translation>Ошибка, мкм</translation>
    </message>
    <message>
        <source>Control interval</source>
        <translation>Интервал управления</translation>
    </message>
    <message>
        <source>Corrective pulse on X</source>
        <translation>Корректирующий импульс на X</translation>
    </message>
    <message>
        <source>Corrective pulse on Z</source>
        <translation>Корректирующий импульс на Z</translation>
    </message>
    <message>
        <source>Pulse, V</source>
        <translation>Импульс, В</translation>
    </message>
    <message>
        <source>Network training</source>
        <translation>Обучение сети</translation>
    </message>
    <message>
        <source>Epoch</source>
        <translation>Эпоха</translation>
    </message>
    <message>
        <source>RMS amplitude error, mV</source>
        <translation>СКО амплитуды, мВ</translation>
    </message>
    <message>
        <source>Training moves</source>
        <translation>Обучающие перемещения</translation>
    </message>
    <message>
        <source>Validation moves</source>
        <translation>Проверочные перемещения</translation>
    </message>
    <message>
        <source>Drift monitor</source>
        <translation>Контроль дрейфа</translation>
    </message>
    <message>
        <source>Corner</source>
        <translation>Угол</translation>
    </message>
    <message>
        <source>Measured − predicted cost, %</source>
        <translation>Изм. − расч. цель, %</translation>
    </message>
    <message>
        <source>Within the threshold</source>
        <translation>В пределах порога</translation>
    </message>
    <message>
        <source>Last %1 corners</source>
        <translation>Последние %1 углов</translation>
    </message>
    <message>
        <source>Retrained</source>
        <translation>Переобучена</translation>
    </message>
    <message>
        <source>Retraining refused</source>
        <translation>Переобучение отклонено</translation>
    </message>
</context>
<context>
    <name>DeviceKinds</name>
    <message>
        <source>Gauge micrometer</source>
        <translation>Цифровой микрометр</translation>
    </message>
    <message>
        <source>Probe mandrel</source>
        <translation>Оправка-датчик</translation>
    </message>
    <message>
        <source>Drive-current readout</source>
        <translation>Датчик тока привода</translation>
    </message>
    <message>
        <source>Correction output to the CNC</source>
        <translation>Выход коррекции в ЧПУ</translation>
    </message>
</context>
<context>
    <name>DeviceSettings</name>
    <message>
        <source>Millimetres</source>
        <translation>Миллиметры</translation>
    </message>
    <message>
        <source>Inches</source>
        <translation>Дюймы</translation>
    </message>
    <message>
        <source>Output format</source>
        <translation>Формат вывода</translation>
    </message>
    <message>
        <source>ASCII data cable (01A+00026.812)</source>
        <translation>Кабель данных ASCII (01A+00026.812)</translation>
    </message>
    <message>
        <source>Digimatic, 13 nibbles</source>
        <translation>Digimatic, 13 полубайтов</translation>
    </message>
    <message>
        <source>Digimatic, hexadecimal text</source>
        <translation>Digimatic, шестнадцатеричный текст</translation>
    </message>
    <message>
        <source>What the data cable or interface sends.</source>
        <translation>Что передаёт кабель данных или интерфейс.</translation>
    </message>
    <message>
        <source>Instrument unit</source>
        <translation>Единица прибора</translation>
    </message>
    <message>
        <source>The unit the micrometer displays; the ASCII format does not say.</source>
        <translation>Единица, в которой показывает микрометр; формат ASCII её не сообщает.</translation>
    </message>
    <message>
        <source>Job unit</source>
        <translation>Единица задания</translation>
    </message>
    <message>
        <source>Readings in another unit are refused, never converted silently.</source>
        <translation>Показания в другой единице отклоняются, а не пересчитываются молча.</translation>
    </message>
    <message>
        <source>Serial port</source>
        <translation>Последовательный порт</translation>
    </message>
    <message>
        <source>The port the cable is plugged into, e.g. /dev/ttyUSB0 or COM3.</source>
        <translation>Порт, к которому подключён кабель, например /dev/ttyUSB0 или COM3.</translation>
    </message>
    <message>
        <source>Baud rate</source>
        <translation>Скорость обмена</translation>
    </message>
    <message>
        <source>bit/s</source>
        <translation>бит/с</translation>
    </message>
    <message>
        <source>Must match the instrument&apos;s setting.</source>
        <translation>Должна совпадать с настройкой прибора.</translation>
    </message>
    <message>
        <source>Data bits</source>
        <translation>Биты данных</translation>
    </message>
    <message>
        <source>Parity</source>
        <translation>Чётность</translation>
    </message>
    <message>
        <source>None</source>
        <translation>Нет</translation>
    </message>
    <message>
        <source>Even</source>
        <translation>Чёт</translation>
    </message>
    <message>
        <source>Odd</source>
        <translation>Нечёт</translation>
    </message>
    <message>
        <source>Stop bits</source>
        <translation>Стоповые биты</translation>
    </message>
    <message>
        <source>%1 to %2</source>
        <translation>от %1 до %2</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is not on or off</source>
        <translation>%1: «%2» — не «вкл» и не «выкл»</translation>
    </message>
    <message>
        <source>%1: a whole number is required</source>
        <translation>%1: требуется целое число</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is not a whole number</source>
        <translation>%1: «%2» — не целое число</translation>
    </message>
    <message>
        <source>%1: %2 is not one of %3</source>
        <translation>%1: %2 не входит в список: %3</translation>
    </message>
    <message>
        <source>%1: %2 is outside %3</source>
        <translation>%1: %2 вне диапазона %3</translation>
    </message>
    <message>
        <source>%1: a number is required</source>
        <translation>%1: требуется число</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is not a number</source>
        <translation>%1: «%2» — не число</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is not one of %3</source>
        <translation>%1: «%2» не входит в список: %3</translation>
    </message>
    <message>
        <source>%1: choose the serial port the device is connected to</source>
        <translation>%1: выберите последовательный порт, к которому подключено устройство</translation>
    </message>
    <message>
        <source>%1: %2 does not exist on this computer (is the cable plugged in?)</source>
        <translation>%1: порта %2 нет на этом компьютере (подключён ли кабель?)</translation>
    </message>
    <message>
        <source>%1: choose a folder</source>
        <translation>%1: выберите папку</translation>
    </message>
    <message>
        <source>%1: the folder %2 does not exist</source>
        <translation>%1: папка %2 не существует</translation>
    </message>
    <message>
        <source>%1: the folder %2 is not writable</source>
        <translation>%1: в папку %2 нельзя записывать</translation>
    </message>
</context>
<context>
    <name>GCodeOutput</name>
    <message>
        <source>the folder %1 does not exist</source>
        <translation>папка %1 не существует</translation>
    </message>
    <message>
        <source>the folder %1 is not writable</source>
        <translation>в папку %1 нельзя записывать</translation>
    </message>
    <message>
        <source>G-code files go to %1</source>
        <translation>файлы G-кода записываются в %1</translation>
    </message>
    <message>
        <source>part %1: %2</source>
        <translation>деталь %1: %2</translation>
    </message>
    <message>
        <source>cannot write %1: %2</source>
        <translation>не удаётся записать %1: %2</translation>
    </message>
    <message>
        <source>a G-code file cannot apply a dynamic X offset; use a Modbus correction output</source>
        <translation>файл G-кода не может задать динамическое смещение по X; используйте выход коррекции Modbus</translation>
    </message>
    <message>
        <source>Files written</source>
        <translation>Записано файлов</translation>
    </message>
    <message>
        <source>Refused</source>
        <translation>Отклонено</translation>
    </message>
    <message>
        <source>Last file</source>
        <translation>Последний файл</translation>
    </message>
    <message>
        <source>none</source>
        <translation>нет</translation>
    </message>
    <message>
        <source>Folder</source>
        <translation>Папка</translation>
    </message>
    <message>
        <source>Where the CNC picks up its programs (network share, DNC folder).</source>
        <translation>Откуда ЧПУ забирает программы (сетевая папка, папка DNC).</translation>
    </message>
    <message>
        <source>File name</source>
        <translation>Имя файла</translation>
    </message>
    <message>
        <source>{part} becomes the part number.</source>
        <translation>{part} заменяется номером детали.</translation>
    </message>
    <message>
        <source>Nominal diameter</source>
        <translation>Номинальный диаметр</translation>
    </message>
    <message>
        <source>mm</source>
        <translation>мм</translation>
    </message>
    <message>
        <source>Finishing feed</source>
        <translation>Чистовая подача</translation>
    </message>
    <message>
        <source>mm/rev</source>
        <translation>мм/об</translation>
    </message>
    <message>
        <source>Spindle speed</source>
        <translation>Частота вращения шпинделя</translation>
    </message>
    <message>
        <source>rpm</source>
        <translation>об/мин</translation>
    </message>
    <message>
        <source>0 leaves the spindle to the main program.</source>
        <translation>0 — шпиндель задаёт основная программа.</translation>
    </message>
    <message>
        <source>X words</source>
        <translation>Значения X</translation>
    </message>
    <message>
        <source>Diameters (diameter mode)</source>
        <translation>Диаметры (программирование на диаметр)</translation>
    </message>
    <message>
        <source>Radii (radius mode)</source>
        <translation>Радиусы (программирование на радиус)</translation>
    </message>
    <message>
        <source>Write G7/G8</source>
        <translation>Записывать G7/G8</translation>
    </message>
    <message>
        <source>For controls that select the X mode by G-code (LinuxCNC).</source>
        <translation>Для систем ЧПУ, выбирающих режим X G-кодом (LinuxCNC).</translation>
    </message>
    <message>
        <source>Machine Z of the part&apos;s left end</source>
        <translation>Машинная координата Z левого торца детали</translation>
    </message>
    <message>
        <source>Z direction along the part</source>
        <translation>Направление Z вдоль детали</translation>
    </message>
    <message>
        <source>Towards the chuck is -Z</source>
        <translation>К патрону — это -Z</translation>
    </message>
    <message>
        <source>Towards the chuck is +Z</source>
        <translation>К патрону — это +Z</translation>
    </message>
    <message>
        <source>Clearance</source>
        <translation>Зазор отвода</translation>
    </message>
    <message>
        <source>Tool</source>
        <translation>Инструмент</translation>
    </message>
    <message>
        <source>Program number</source>
        <translation>Номер программы</translation>
    </message>
    <message>
        <source>Correction limit</source>
        <translation>Предел коррекции</translation>
    </message>
    <message>
        <source>A path with a larger correction is refused, never written.</source>
        <translation>Траектория с большей коррекцией отклоняется и не записывается.</translation>
    </message>
    <message>
        <source>G-code file</source>
        <translation>Файл G-кода</translation>
    </message>
</context>
<context>
    <name>LinuxCnc</name>
    <message>
        <source>Host: enter the IP address or name of the LinuxCNC computer</source>
        <translation>Хост: введите IP-адрес или имя компьютера LinuxCNC</translation>
    </message>
    <message>
        <source>%1: one word without spaces (the remote shell splits at spaces)</source>
        <translation>%1: одно слово без пробелов (удалённая оболочка делит строку по пробелам)</translation>
    </message>
    <message>
        <source>Largest step: must not exceed the largest total</source>
        <translation>Наибольший шаг: не должен превышать наибольшую коррекцию</translation>
    </message>
    <message>
        <source>Part program: an absolute path on the LinuxCNC computer</source>
        <translation>Управляющая программа: абсолютный путь на компьютере LinuxCNC</translation>
    </message>
    <message>
        <source>LinuxCNC lathe (%1)</source>
        <translation>Станок LinuxCNC (%1)</translation>
    </message>
    <message>
        <source>LinuxCNC machines every part; the simulated shaft&apos;s physics is applied to the path LinuxCNC executed and the simulated micrometer measures it; TrueTurn writes the corrections into LinuxCNC between parts.</source>
        <translation>LinuxCNC обрабатывает каждую деталь; физика моделируемого вала применяется к траектории, которую выполнил LinuxCNC, и моделируемый микрометр её измеряет; TrueTurn записывает коррекции в LinuxCNC между деталями.</translation>
    </message>
    <message>
        <source>yes</source>
        <translation>да</translation>
    </message>
    <message>
        <source>no</source>
        <translation>нет</translation>
    </message>
    <message>
        <source>E-stop on</source>
        <translation>аварийный стоп</translation>
    </message>
    <message>
        <source>on</source>
        <translation>включён</translation>
    </message>
    <message>
        <source>off</source>
        <translation>выключен</translation>
    </message>
    <message>
        <source>idle</source>
        <translation>не выполняется</translation>
    </message>
    <message>
        <source>running</source>
        <translation>выполняется</translation>
    </message>
    <message>
        <source>paused</source>
        <translation>приостановлена</translation>
    </message>
    <message>
        <source>inch</source>
        <translation>дюйм</translation>
    </message>
    <message>
        <source>cm</source>
        <translation>см</translation>
    </message>
    <message>
        <source>mm</source>
        <translation>мм</translation>
    </message>
    <message>
        <source>no part program is set for LinuxCNC; the operator runs the parts</source>
        <translation>для LinuxCNC не задана управляющая программа; детали запускает оператор</translation>
    </message>
    <message>
        <source>no corrections were sent for part %1</source>
        <translation>для детали %1 коррекции не переданы</translation>
    </message>
    <message>
        <source>connecting to %1</source>
        <translation>подключение к %1</translation>
    </message>
    <message>
        <source>%1; X %2 Z %3 mm</source>
        <translation>%1; X %2 Z %3 мм</translation>
    </message>
    <message>
        <source>part %1: no corrections</source>
        <translation>деталь %1: нет коррекций</translation>
    </message>
    <message>
        <source>%1: part %2: %3; nothing written</source>
        <translation>%1: деталь %2: %3; ничего не записано</translation>
    </message>
    <message>
        <source>LinuxCNC takes corrections between parts; a dynamic X offset needs a PLC (Modbus output)</source>
        <translation>LinuxCNC принимает коррекции между деталями; динамическому смещению X нужен ПЛК (выход Modbus)</translation>
    </message>
    <message>
        <source>LinuxCNC</source>
        <translation>LinuxCNC</translation>
    </message>
    <message>
        <source>remote shell %1, protocol %2</source>
        <translation>удалённая оболочка %1, протокол %2</translation>
    </message>
    <message>
        <source>Machine units</source>
        <translation>Единицы станка</translation>
    </message>
    <message>
        <source>Machine</source>
        <translation>Станок</translation>
    </message>
    <message>
        <source>Homed</source>
        <translation>Реферирован</translation>
    </message>
    <message>
        <source>Program</source>
        <translation>Программа</translation>
    </message>
    <message>
        <source>Position</source>
        <translation>Положение</translation>
    </message>
    <message>
        <source>X %1 Z %2 mm</source>
        <translation>X %1 Z %2 мм</translation>
    </message>
    <message>
        <source>Program units</source>
        <translation>Единицы программы</translation>
    </message>
    <message>
        <source>inch (G20)</source>
        <translation>дюймы (G20)</translation>
    </message>
    <message>
        <source>mm (G21)</source>
        <translation>мм (G21)</translation>
    </message>
    <message>
        <source>diameter (G7)</source>
        <translation>диаметр (G7)</translation>
    </message>
    <message>
        <source>radius (G8)</source>
        <translation>радиус (G8)</translation>
    </message>
    <message>
        <source>Writes verified</source>
        <translation>Записей проверено</translation>
    </message>
    <message>
        <source>Writes refused</source>
        <translation>Записей отклонено</translation>
    </message>
    <message>
        <source>Read-backs that differed</source>
        <translation>Расхождений при обратном чтении</translation>
    </message>
    <message>
        <source>Writes held (machine not ready)</source>
        <translation>Записей отложено (станок не готов)</translation>
    </message>
    <message>
        <source>Connection resets</source>
        <translation>Сбросов соединения</translation>
    </message>
    <message>
        <source>Parts cut</source>
        <translation>Деталей обработано</translation>
    </message>
    <message>
        <source>Parts aborted</source>
        <translation>Деталей прервано</translation>
    </message>
    <message>
        <source>Host</source>
        <translation>Хост</translation>
    </message>
    <message>
        <source>IP address or name of the LinuxCNC computer (its remote shell, linuxcncrsh).</source>
        <translation>IP-адрес или имя компьютера LinuxCNC (его удалённой оболочки linuxcncrsh).</translation>
    </message>
    <message>
        <source>TCP port</source>
        <translation>Порт TCP</translation>
    </message>
    <message>
        <source>Connect password</source>
        <translation>Пароль подключения</translation>
    </message>
    <message>
        <source>linuxcncrsh --connectpw; sent in clear text.</source>
        <translation>linuxcncrsh --connectpw; передаётся открытым текстом.</translation>
    </message>
    <message>
        <source>Enable password</source>
        <translation>Пароль управления</translation>
    </message>
    <message>
        <source>linuxcncrsh --enablepw: the right to command the machine; sent in clear text.</source>
        <translation>linuxcncrsh --enablepw: право управлять станком; передаётся открытым текстом.</translation>
    </message>
    <message>
        <source>Client name</source>
        <translation>Имя клиента</translation>
    </message>
    <message>
        <source>How TrueTurn introduces itself (one word).</source>
        <translation>Как TrueTurn представляется (одно слово).</translation>
    </message>
    <message>
        <source>Connect timeout</source>
        <translation>Тайм-аут подключения</translation>
    </message>
    <message>
        <source>ms</source>
        <translation>мс</translation>
    </message>
    <message>
        <source>Reply timeout</source>
        <translation>Тайм-аут ответа</translation>
    </message>
    <message>
        <source>A reply, a mode change or an MDI line; the connection is reset without it.</source>
        <translation>Ответ, смена режима или строка MDI; без ответа соединение сбрасывается.</translation>
    </message>
    <message>
        <source>Joints to be homed</source>
        <translation>Осей для реферирования</translation>
    </message>
    <message>
        <source>A lathe: 2 (X and Z).</source>
        <translation>Токарный станок: 2 (X и Z).</translation>
    </message>
    <message>
        <source>How the correction reaches the cut</source>
        <translation>Как коррекция попадает в резание</translation>
    </message>
    <message>
        <source>Profile: the control-point corrections as numbered parameters</source>
        <translation>Профиль: коррекции контрольных точек как нумерованные параметры</translation>
    </message>
    <message>
        <source>Wear: one diameter correction as the tool&apos;s X wear</source>
        <translation>Износ: одна коррекция диаметра как износ инструмента по X</translation>
    </message>
    <message>
        <source>First parameter</source>
        <translation>Первый параметр</translation>
    </message>
    <message>
        <source>#500 .. #504 hold the corrections, #505 the part number they are for.</source>
        <translation>#500 .. #504 хранят коррекции, #505 — номер детали, для которой они записаны.</translation>
    </message>
    <message>
        <source>Tool</source>
        <translation>Инструмент</translation>
    </message>
    <message>
        <source>Wear entry (tool number)</source>
        <translation>Запись износа (номер инструмента)</translation>
    </message>
    <message>
        <source>Its X wear is set by G10 L1; the part program applies it with G43.2 H&lt;entry&gt;.</source>
        <translation>Её износ по X задаётся G10 L1; управляющая программа применяет его командой G43.2 H&lt;запись&gt;.</translation>
    </message>
    <message>
        <source>X words of the part program</source>
        <translation>Слова X управляющей программы</translation>
    </message>
    <message>
        <source>Diameters (G7)</source>
        <translation>Диаметры (G7)</translation>
    </message>
    <message>
        <source>Radii (G8)</source>
        <translation>Радиусы (G8)</translation>
    </message>
    <message>
        <source>Units of the part program</source>
        <translation>Единицы управляющей программы</translation>
    </message>
    <message>
        <source>Millimetres (G21)</source>
        <translation>Миллиметры (G21)</translation>
    </message>
    <message>
        <source>Inches (G20)</source>
        <translation>Дюймы (G20)</translation>
    </message>
    <message>
        <source>Largest step</source>
        <translation>Наибольший шаг</translation>
    </message>
    <message>
        <source>Largest change of a correction from part to part (radial); larger is never written.</source>
        <translation>Наибольшее изменение коррекции от детали к детали (на радиус); большее никогда не записывается.</translation>
    </message>
    <message>
        <source>Largest total</source>
        <translation>Наибольшая коррекция</translation>
    </message>
    <message>
        <source>Largest correction (radial); larger is never written.</source>
        <translation>Наибольшая коррекция (на радиус); большая никогда не записывается.</translation>
    </message>
    <message>
        <source>Part program on the LinuxCNC computer</source>
        <translation>Управляющая программа на компьютере LinuxCNC</translation>
    </message>
    <message>
        <source>Empty: the operator runs the parts; TrueTurn writes between them.</source>
        <translation>Пусто: детали запускает оператор; TrueTurn записывает коррекции между ними.</translation>
    </message>
    <message>
        <source>TrueTurn presses cycle start</source>
        <translation>TrueTurn нажимает «Пуск цикла»</translation>
    </message>
    <message>
        <source>Otherwise the operator presses it after TrueTurn has written the corrections.</source>
        <translation>Иначе её нажимает оператор после того, как TrueTurn записал коррекции.</translation>
    </message>
    <message>
        <source>LinuxCNC at %1:%2</source>
        <translation>LinuxCNC на %1:%2</translation>
    </message>
    <message>
        <source>LinuxCNC remote shell (TCP)</source>
        <translation>Удалённая оболочка LinuxCNC (TCP)</translation>
    </message>
</context>
<context>
    <name>Modbus</name>
    <message>
        <source>connecting to %1</source>
        <translation>подключение к %1</translation>
    </message>
    <message>
        <source>connected to %1; reading</source>
        <translation>подключено к %1; чтение</translation>
    </message>
    <message>
        <source>cannot send the request to %1</source>
        <translation>не удаётся отправить запрос в %1</translation>
    </message>
    <message>
        <source>%1 (%2 polls in a row)</source>
        <translation>%1 (опросов подряд: %2)</translation>
    </message>
    <message>
        <source>sample refused: %1</source>
        <translation>отсчёт отклонён: %1</translation>
    </message>
    <message>
        <source>polling %1</source>
        <translation>опрос %1</translation>
    </message>
    <message>
        <source>%1 A, %2 mm/s, %3 mm</source>
        <translation>%1 А, %2 мм/с, %3 мм</translation>
    </message>
    <message>
        <source>Polls</source>
        <translation>Опросов</translation>
    </message>
    <message>
        <source>Samples</source>
        <translation>Отсчётов</translation>
    </message>
    <message>
        <source>Timeouts</source>
        <translation>Тайм-аутов</translation>
    </message>
    <message>
        <source>Modbus exceptions</source>
        <translation>Исключений Modbus</translation>
    </message>
    <message>
        <source>Samples refused</source>
        <translation>Отклонено отсчётов</translation>
    </message>
    <message>
        <source>Polls skipped (previous still running)</source>
        <translation>Пропущено опросов (предыдущий не завершён)</translation>
    </message>
    <message>
        <source>Current</source>
        <translation>Ток</translation>
    </message>
    <message>
        <source>Velocity</source>
        <translation>Скорость</translation>
    </message>
    <message>
        <source>Position</source>
        <translation>Положение</translation>
    </message>
    <message>
        <source>Polling period</source>
        <translation>Период опроса</translation>
    </message>
    <message>
        <source>ms</source>
        <translation>мс</translation>
    </message>
    <message>
        <source>The PLC cycle of paper 001: 10 to 100 ms.</source>
        <translation>Цикл ПЛК по статье 001: от 10 до 100 мс.</translation>
    </message>
    <message>
        <source>What is written</source>
        <translation>Что записывается</translation>
    </message>
    <message>
        <source>Per-point corrections of the next part</source>
        <translation>Коррекции по точкам для следующей детали</translation>
    </message>
    <message>
        <source>Dynamic X offset, every PLC cycle</source>
        <translation>Динамическое смещение по X в каждом цикле ПЛК</translation>
    </message>
    <message>
        <source>First correction register</source>
        <translation>Первый регистр коррекций</translation>
    </message>
    <message>
        <source>Control points</source>
        <translation>Контрольные точки</translation>
    </message>
    <message>
        <source>Paper 000 controls five points.</source>
        <translation>В статье 000 регулируются пять точек.</translation>
    </message>
    <message>
        <source>Write the part number last</source>
        <translation>Записывать номер детали последним</translation>
    </message>
    <message>
        <source>A handshake: the PLC applies the corrections when the number changes.</source>
        <translation>Квитирование: ПЛК применяет коррекции при смене номера.</translation>
    </message>
    <message>
        <source>Part number register (int32)</source>
        <translation>Регистр номера детали (int32)</translation>
    </message>
    <message>
        <source>X offset register</source>
        <translation>Регистр смещения по X</translation>
    </message>
    <message>
        <source>Correction</source>
        <translation>Коррекция</translation>
    </message>
    <message>
        <source>mm per count</source>
        <translation>мм на единицу</translation>
    </message>
    <message>
        <source>Correction limit</source>
        <translation>Предел коррекции</translation>
    </message>
    <message>
        <source>mm</source>
        <translation>мм</translation>
    </message>
    <message>
        <source>Larger corrections are refused, never sent.</source>
        <translation>Большие коррекции отклоняются и не передаются.</translation>
    </message>
    <message>
        <source>Host: enter the IP address or name of the drive or PLC</source>
        <translation>Хост: введите IP-адрес или имя привода или ПЛК</translation>
    </message>
    <message>
        <source>%1: the scale must not be zero</source>
        <translation>%1: масштаб не должен быть нулевым</translation>
    </message>
    <message>
        <source>First correction register: the corrections run past address 65535</source>
        <translation>Первый регистр коррекций: коррекции выходят за адрес 65535</translation>
    </message>
    <message>
        <source>Correction: the scale must not be zero</source>
        <translation>Коррекция: масштаб не должен быть нулевым</translation>
    </message>
    <message>
        <source>Correction: type must be signed (corrections can be negative)</source>
        <translation>Коррекция: тип должен быть знаковым (коррекции бывают отрицательными)</translation>
    </message>
    <message>
        <source>connection closed</source>
        <translation>соединение закрыто</translation>
    </message>
    <message>
        <source>lost the connection to %1 (%2)</source>
        <translation>потеряно соединение с %1 (%2)</translation>
    </message>
    <message>
        <source>cannot connect to %1 (%2)</source>
        <translation>не удаётся подключиться к %1 (%2)</translation>
    </message>
    <message numerus="yes">
        <source>reading %n register(s) from %1</source>
        <translation>
            <numerusform>чтение %n регистра с адреса %1</numerusform>
            <numerusform>чтение %n регистров с адреса %1</numerusform>
            <numerusform>чтение %n регистров с адреса %1</numerusform>
        </translation>
    </message>
    <message>
        <source>Modbus exception %1 (%2) %3 of %4</source>
        <translation>исключение Modbus %1 (%2): %3, %4</translation>
    </message>
    <message>
        <source>invalid reply %1 of %2: %3</source>
        <translation>неверный ответ: %1, %2: %3</translation>
    </message>
    <message>
        <source>no answer from %1 within %2 ms (%3)</source>
        <translation>нет ответа от %1 в течение %2 мс (%3)</translation>
    </message>
    <message>
        <source>%1 of %2 failed: %3</source>
        <translation>сбой: %1, %2: %3</translation>
    </message>
    <message>
        <source>connected to %1</source>
        <translation>подключено к %1</translation>
    </message>
    <message>
        <source>connected to %1; registers readable</source>
        <translation>подключено к %1; регистры читаются</translation>
    </message>
    <message>
        <source>this output is set up for the dynamic X offset, not per-point corrections</source>
        <translation>этот выход настроен на динамическое смещение по X, а не на коррекции по точкам</translation>
    </message>
    <message>
        <source>part %1 has %2 corrections; this output takes 1 to %3</source>
        <translation>у детали %1 коррекций: %2; этот выход принимает от 1 до %3</translation>
    </message>
    <message>
        <source>corrections of part %1</source>
        <translation>коррекции детали %1</translation>
    </message>
    <message>
        <source>part %1: correction %2 mm is beyond the limit of %3 mm; nothing sent</source>
        <translation>деталь %1: коррекция %2 мм выходит за предел %3 мм; ничего не отправлено</translation>
    </message>
    <message>
        <source>part %1: %2</source>
        <translation>деталь %1: %2</translation>
    </message>
    <message>
        <source>part number %1</source>
        <translation>номер детали %1</translation>
    </message>
    <message>
        <source>part %1: %2 corrections written and verified</source>
        <translation>деталь %1: коррекции записаны и проверены (%2)</translation>
    </message>
    <message>
        <source>this output is set up for per-point corrections, not the dynamic X offset</source>
        <translation>этот выход настроен на коррекции по точкам, а не на динамическое смещение по X</translation>
    </message>
    <message>
        <source>X offset %1 mm is beyond the limit of %2 mm; nothing sent</source>
        <translation>смещение по X %1 мм выходит за предел %2 мм; ничего не отправлено</translation>
    </message>
    <message>
        <source>X offset %1 mm</source>
        <translation>смещение по X %1 мм</translation>
    </message>
    <message>
        <source>X offset %1 mm written and verified</source>
        <translation>смещение по X %1 мм записано и проверено</translation>
    </message>
    <message>
        <source>%1 is not connected</source>
        <translation>%1: нет подключения</translation>
    </message>
    <message>
        <source>cannot send %1 to %2</source>
        <translation>не удаётся отправить %1 в %2</translation>
    </message>
    <message>
        <source>cannot read back %1 from %2</source>
        <translation>контрольное считывание не удалось: %1, %2</translation>
    </message>
    <message>
        <source>read-back mismatch for %1 at register %2: wrote %3, read %4</source>
        <translation>контрольное считывание не совпадает (%1, регистр %2): записано %3, считано %4</translation>
    </message>
    <message>
        <source>Writes verified</source>
        <translation>Проверенных записей</translation>
    </message>
    <message>
        <source>Refused or failed</source>
        <translation>Отклонено или с ошибкой</translation>
    </message>
    <message>
        <source>Connection</source>
        <translation>Подключение</translation>
    </message>
    <message>
        <source>Modbus TCP (Ethernet)</source>
        <translation>Modbus TCP (Ethernet)</translation>
    </message>
    <message>
        <source>Modbus RTU (serial)</source>
        <translation>Modbus RTU (последовательный порт)</translation>
    </message>
    <message>
        <source>Host</source>
        <translation>Хост</translation>
    </message>
    <message>
        <source>IP address or name of the drive or PLC.</source>
        <translation>IP-адрес или имя привода или ПЛК.</translation>
    </message>
    <message>
        <source>TCP port</source>
        <translation>TCP-порт</translation>
    </message>
    <message>
        <source>Unit id</source>
        <translation>Адрес устройства</translation>
    </message>
    <message>
        <source>The server address of the drive or PLC.</source>
        <translation>Адрес привода или ПЛК в сети Modbus (Unit ID).</translation>
    </message>
    <message>
        <source>Reply timeout</source>
        <translation>Тайм-аут ответа</translation>
    </message>
    <message>
        <source>Retries</source>
        <translation>Повторы</translation>
    </message>
    <message>
        <source>%1: registers</source>
        <translation>%1: регистры</translation>
    </message>
    <message>
        <source>Holding (4x)</source>
        <translation>Хранения (4x)</translation>
    </message>
    <message>
        <source>Input (3x)</source>
        <translation>Входные (3x)</translation>
    </message>
    <message>
        <source>%1: address</source>
        <translation>%1: адрес</translation>
    </message>
    <message>
        <source>Zero-based protocol address.</source>
        <translation>Адрес в протоколе, отсчёт от нуля.</translation>
    </message>
    <message>
        <source>%1: type</source>
        <translation>%1: тип</translation>
    </message>
    <message>
        <source>%1: word order</source>
        <translation>%1: порядок слов</translation>
    </message>
    <message>
        <source>High word first</source>
        <translation>Старшее слово первым</translation>
    </message>
    <message>
        <source>Low word first</source>
        <translation>Младшее слово первым</translation>
    </message>
    <message>
        <source>%1: scale</source>
        <translation>%1: масштаб</translation>
    </message>
    <message>
        <source>per count</source>
        <translation>на единицу</translation>
    </message>
    <message>
        <source>Value = register x scale (in the unit below).</source>
        <translation>Значение = регистр × масштаб (в единице ниже).</translation>
    </message>
    <message>
        <source>%1: unit</source>
        <translation>%1: единица</translation>
    </message>
    <message>
        <source>unit %1</source>
        <translation>устройство %1</translation>
    </message>
    <message numerus="yes">
        <source>writing %n register(s) at %1</source>
        <translation>
            <numerusform>запись %n регистра по адресу %1</numerusform>
            <numerusform>запись %n регистров по адресу %1</numerusform>
            <numerusform>запись %n регистров по адресу %1</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>Notice</name>
    <message>
        <source>Part %1, point %2: %3</source>
        <translation>Деталь %1, точка %2: %3</translation>
    </message>
    <message>
        <source>Starting part %1</source>
        <translation>Запуск детали %1</translation>
    </message>
    <message>
        <source>Continuing run %1 with part %2</source>
        <translation>Продолжение цикла %1 с детали %2</translation>
    </message>
    <message>
        <source>Paused by the operator; the CNC keeps the last correction</source>
        <translation>Пауза по команде оператора; ЧПУ сохраняет последнюю коррекцию</translation>
    </message>
    <message>
        <source>Machining part %1</source>
        <translation>Обработка детали %1</translation>
    </message>
    <message>
        <source>Continuing</source>
        <translation>Продолжение</translation>
    </message>
    <message>
        <source>Stopped</source>
        <translation>Остановлено</translation>
    </message>
    <message>
        <source>The gauge answers again; continuing</source>
        <translation>Измерительный прибор снова отвечает; продолжение</translation>
    </message>
    <message>
        <source>Measuring the last parts (part %1 next)</source>
        <translation>Измерение последних деталей (следующая — деталь %1)</translation>
    </message>
    <message>
        <source>Waiting for the diameters of part %1</source>
        <translation>Ожидание диаметров детали %1</translation>
    </message>
    <message>
        <source>The gauge is not ready (%1); part %2 needs the diameters of part %3. Paused, the CNC keeps the last correction</source>
        <translation>Измерительный прибор не готов (%1); для детали %2 нужны диаметры детали %3. Пауза, ЧПУ сохраняет последнюю коррекцию</translation>
    </message>
    <message>
        <source>No diameters of part %1 for %2 min. Paused, the CNC keeps the last correction</source>
        <translation>Нет диаметров детали %1 уже %2 мин. Пауза, ЧПУ сохраняет последнюю коррекцию</translation>
    </message>
    <message>
        <source>Run complete: part %1 was the last</source>
        <translation>Цикл завершён: деталь %1 была последней</translation>
    </message>
    <message>
        <source>Part %1 finished</source>
        <translation>Деталь %1 готова</translation>
    </message>
    <message>
        <source>Part %1 measured</source>
        <translation>Деталь %1 измерена</translation>
    </message>
    <message>
        <source>Part %1 was on the machine when the run was stopped; it is not recorded</source>
        <translation>Деталь %1 была на станке при остановке цикла; она не записана</translation>
    </message>
    <message>
        <source>The end of the run could not be stored: %1</source>
        <translation>Не удалось записать завершение цикла: %1</translation>
    </message>
    <message>
        <source>The machine reported part %1 finished, which the loop did not start; ignored</source>
        <translation>Станок сообщил о готовности детали %1, которую контур не запускал; сообщение пропущено</translation>
    </message>
    <message>
        <source>The history could not be written, part %1 is not stored (%2); the CNC keeps the last correction</source>
        <translation>Не удалось записать историю, деталь %1 не сохранена (%2); ЧПУ сохраняет последнюю коррекцию</translation>
    </message>
    <message>
        <source>A reading of %1 mm arrived but no part is waiting to be measured; it was ignored</source>
        <translation>Пришло показание %1 мм, но ни одна деталь не ждёт измерения; оно пропущено</translation>
    </message>
    <message>
        <source>The diameters of part %1 could not be stored (%2); the CNC keeps the last correction</source>
        <translation>Не удалось сохранить диаметры детали %1 (%2); ЧПУ сохраняет последнюю коррекцию</translation>
    </message>
    <message>
        <source>The corrections for part %1 could not be computed (%2); the CNC keeps the last correction</source>
        <translation>Не удалось вычислить коррекции для детали %1 (%2); ЧПУ сохраняет последнюю коррекцию</translation>
    </message>
    <message>
        <source>Part %1: the controller gave no usable correction at point %2 (x = %3 mm); holding %4 mm</source>
        <translation>Деталь %1: регулятор не дал пригодной коррекции в точке %2 (x = %3 мм); сохраняется %4 мм</translation>
    </message>
    <message>
        <source>Part %1: correction at point %2 (x = %3 mm) limited from %4 to %5 mm</source>
        <translation>Деталь %1: коррекция в точке %2 (x = %3 мм) ограничена с %4 до %5 мм</translation>
    </message>
    <message>
        <source>The CNC refused the corrections for part %1: %2; it keeps the last correction</source>
        <translation>ЧПУ не приняло коррекции для детали %1: %2; сохраняется последняя коррекция</translation>
    </message>
    <message>
        <source>The machine did not start part %1: %2</source>
        <translation>Станок не запустил деталь %1: %2</translation>
    </message>
    <message>
        <source>not measured</source>
        <translation>не измерено</translation>
    </message>
    <message>
        <source>not measured: skipped by the operator</source>
        <translation>не измерено: пропущено оператором</translation>
    </message>
    <message>
        <source>the reading is not a number</source>
        <translation>показание не является числом</translation>
    </message>
    <message>
        <source>not a finite number</source>
        <translation>не конечное число</translation>
    </message>
    <message>
        <source>every control point already has a reading; re-take a point to replace it</source>
        <translation>во всех контрольных точках уже есть показания; чтобы заменить показание, измерьте точку заново</translation>
    </message>
    <message>
        <source>reading %1 mm is more than %2 mm from the nominal %3 mm; check the point (x = %4 mm) and measure again</source>
        <translation>показание %1 мм отличается от номинала %3 мм больше чем на %2 мм; проверьте точку (x = %4 мм) и измерьте снова</translation>
    </message>
    <message>
        <source>the point was already measured for part %1</source>
        <translation>точка уже измерена для детали %1</translation>
    </message>
    <message>
        <source>part %1 has not been machined yet</source>
        <translation>деталь %1 ещё не обработана</translation>
    </message>
    <message>
        <source>part %1 was not machined under this controller</source>
        <translation>деталь %1 обработана не под этим регулятором</translation>
    </message>
    <message>
        <source>part %1 is too late: the controller keeps the last %2 parts</source>
        <translation>деталь %1 опоздала: регулятор хранит последние %2 деталей</translation>
    </message>
    <message>
        <source>rejected by the controller: %1 σ from the prediction (gate %2 σ)</source>
        <translation>отклонено регулятором: %1 σ от прогноза (порог %2 σ)</translation>
    </message>
    <message>
        <source>rejected by the controller: the deviation %1 mm reaches the alarm band %2 mm; check the part</source>
        <translation>отклонено регулятором: отклонение %1 мм достигает аварийной границы %2 мм; проверьте деталь</translation>
    </message>
    <message>
        <source>the controller could not use it: %1</source>
        <translation>регулятор не смог его использовать: %1</translation>
    </message>
    <message>
        <source>rejected by the controller: %1</source>
        <translation>отклонено регулятором: %1</translation>
    </message>
    <message>
        <source>Paused: part %1 is scrap; check the machine, then continue. The CNC keeps the last correction</source>
        <translation>Пауза: деталь %1 — брак; проверьте станок и продолжите. ЧПУ сохраняет последнюю коррекцию</translation>
    </message>
    <message>
        <source>Part %1, point %2 (x = %3 mm): %4 mm is %5 mm above the upper limit %6 mm: rework</source>
        <translation>Деталь %1, точка %2 (x = %3 мм): %4 мм на %5 мм больше верхнего предела %6 мм: исправимый брак</translation>
    </message>
    <message>
        <source>Part %1, point %2 (x = %3 mm): %4 mm is %5 mm below the lower limit %6 mm: scrap</source>
        <translation>Деталь %1, точка %2 (x = %3 мм): %4 мм на %5 мм меньше нижнего предела %6 мм: неисправимый брак</translation>
    </message>
    <message>
        <source>correlation</source>
        <translation>корреляционный</translation>
    </message>
    <message>
        <source>variance</source>
        <translation>дисперсионный</translation>
    </message>
    <message>
        <source>The CNC keeps the last correction until the run is restarted</source>
        <translation>ЧПУ сохраняет последнюю коррекцию до перезапуска серии</translation>
    </message>
    <message>
        <source>The controller goes on</source>
        <translation>Регулятор продолжает работу</translation>
    </message>
    <message>
        <source>The plant no longer matches the controller&apos;s model (part %1, point %2): the %3 test of the innovations over %4 parts is %5, above its limit %6. %7</source>
        <translation>Объект больше не соответствует модели регулятора (деталь %1, точка %2): %3 критерий невязок за %4 деталей равен %5, выше предела %6. %7</translation>
    </message>
    <message>
        <source>Paused before part %1: the history takes no new part (%2). The run goes on by itself when it does; the CNC keeps the last correction</source>
        <translation>Пауза перед деталью %1: история не принимает новых деталей (%2). Работа продолжится сама, когда примет; ЧПУ держит последнюю коррекцию</translation>
    </message>
    <message>
        <source>The loop switches to its robust fallback and identifies the plant</source>
        <translation>Контур переходит на робастный резервный регулятор и идентифицирует объект</translation>
    </message>
    <message>
        <source>From part %1 the loop corrects with its robust fallback (EWMA, weight %2: stable for plant gains 0.5 to 2 times the model&apos;s and one more part of delay) while it identifies the plant</source>
        <translation>С детали %1 контур корректирует резервным регулятором (EWMA, вес %2: устойчив при коэффициенте объекта от 0,5 до 2 модельного и задержке на одну деталь больше), пока идентифицирует объект</translation>
    </message>
    <message>
        <source>Part %1: the plant cannot be identified yet: %2</source>
        <translation>Деталь %1: объект пока нельзя идентифицировать: %2</translation>
    </message>
    <message>
        <source>From part %1 the loop corrects with an LQG designed for the plant identified from %2 (plant delay %3 parts, smallest gain margin %4); the mismatch monitor restarts on that model</source>
        <translation>С детали %1 контур корректирует LQG-регулятором, рассчитанным для объекта, идентифицированного по %2 (задержка объекта %3 дет., наименьший запас по усилению %4); контроль несоответствия начинается заново по этой модели</translation>
    </message>
    <message>
        <source>Part %1: an LQG for the plant identified from %2 (plant delay %3 parts) is proposed; the fallback goes on until an engineer applies it on the Controller page</source>
        <translation>Деталь %1: предложен LQG-регулятор для объекта, идентифицированного по %2 (задержка объекта %3 дет.); резервный регулятор работает, пока инженер не применит его на странице «Регулятор»</translation>
    </message>
    <message>
        <source>Part %1: the design for the identified plant is not applied: %2; the fallback goes on</source>
        <translation>Деталь %1: расчёт для идентифицированного объекта не применён: %2; резервный регулятор продолжает работу</translation>
    </message>
    <message>
        <source>From part %1 the loop corrects with the proposed LQG an engineer applied</source>
        <translation>С детали %1 контур корректирует предложенным LQG-регулятором, который применил инженер</translation>
    </message>
    <message>
        <source>independence</source>
        <translation>перекрёстный</translation>
    </message>
    <message>
        <source>Controller: robust EWMA fallback (weight %1) from part %2, while the plant is identified</source>
        <translation>Регулятор: резервный EWMA (вес %1) с детали %2, пока идентифицируется объект</translation>
    </message>
    <message>
        <source>Controller: LQG adapted at part %1 (plant delay %2 parts, smallest gain margin %3)</source>
        <translation>Регулятор: LQG, адаптирован на детали %1 (задержка объекта %2 дет., наименьший запас по усилению %3)</translation>
    </message>
    <message>
        <source>Controller: robust EWMA fallback; a new design waits for an engineer&apos;s Apply (Controller page)</source>
        <translation>Регулятор: резервный EWMA; новый расчёт ждёт применения инженером (страница «Регулятор»)</translation>
    </message>
    <message>
        <source>Controller: robust EWMA fallback; the new design was not applied: %1</source>
        <translation>Регулятор: резервный EWMA; новый расчёт не применён: %1</translation>
    </message>
    <message>
        <source>Controller: LQG applied by an engineer at part %1</source>
        <translation>Регулятор: LQG, применён инженером на детали %1</translation>
    </message>
</context>
<context>
    <name>ProbeMandrel</name>
    <message>
        <source>Sample rate</source>
        <translation>Частота отсчётов</translation>
    </message>
    <message>
        <source>Hz</source>
        <translation>Гц</translation>
    </message>
    <message>
        <source>The PLC applies the correction every 10 to 100 ms (paper 001).</source>
        <translation>ПЛК применяет коррекцию с периодом от 10 до 100 мс (статья 001).</translation>
    </message>
    <message>
        <source>Silence timeout</source>
        <translation>Тайм-аут молчания</translation>
    </message>
    <message>
        <source>ms</source>
        <translation>мс</translation>
    </message>
    <message>
        <source>No data for this long: the probe is in error.</source>
        <translation>Если данных нет так долго, датчик переходит в состояние ошибки.</translation>
    </message>
    <message>
        <source>Command timeout</source>
        <translation>Тайм-аут команды</translation>
    </message>
    <message>
        <source>Serial RS-232/RS-485</source>
        <translation>Последовательный порт RS-232/RS-485</translation>
    </message>
    <message>
        <source>probe mandrel</source>
        <translation>оправка-датчик</translation>
    </message>
    <message>
        <source>opening %1</source>
        <translation>открытие %1</translation>
    </message>
    <message>
        <source>streaming from %1</source>
        <translation>поток данных с %1</translation>
    </message>
    <message>
        <source>starting the probe mandrel on %1</source>
        <translation>запуск оправки-датчика на %1</translation>
    </message>
    <message>
        <source>%1 on %2</source>
        <translation>%1 (%2)</translation>
    </message>
</context>
<context>
    <name>ProbeStatus</name>
    <message>
        <source>Samples used</source>
        <translation>Использовано отсчётов</translation>
    </message>
    <message>
        <source>Frames lost</source>
        <translation>Потеряно кадров</translation>
    </message>
    <message>
        <source>Frames duplicated</source>
        <translation>Повторных кадров</translation>
    </message>
    <message>
        <source>Frames corrupt</source>
        <translation>Искажённых кадров</translation>
    </message>
    <message>
        <source>Samples dropped (over-range, excitation)</source>
        <translation>Отброшено отсчётов (перегрузка, возбуждение)</translation>
    </message>
    <message>
        <source>Commands resent</source>
        <translation>Повторно отправлено команд</translation>
    </message>
    <message>
        <source>Samples not taken in time</source>
        <translation>Отсчётов не взято вовремя</translation>
    </message>
    <message>
        <source>Protocol</source>
        <translation>Протокол</translation>
    </message>
    <message>
        <source>%1 (tables up to %2 KiB, CRC-32C)</source>
        <translation>%1 (таблицы до %2 КиБ, CRC-32C)</translation>
    </message>
    <message>
        <source>1 (tables up to 64 KiB, CRC-16)</source>
        <translation>1 (таблицы до 64 КиБ, CRC-16)</translation>
    </message>
    <message>
        <source>Linearisation table</source>
        <translation>Таблица линеаризации</translation>
    </message>
    <message>
        <source>version %1, %2, %3 bytes</source>
        <translation>версия %1, %2, байт: %3</translation>
    </message>
    <message>
        <source>none (raw ADC codes only)</source>
        <translation>нет (только необработанные коды АЦП)</translation>
    </message>
    <message>
        <source>%1 / %2 mm</source>
        <translation>%1 / %2 мм</translation>
    </message>
</context>
<context>
    <name>ProcedureWords</name>
    <message>
        <source>The ADC saturated here (raw codes %1 to %2, limits 0 and %3): the point is kept but not used in the fit.</source>
        <translation>Здесь АЦП в насыщении (коды от %1 до %2 при пределах 0 и %3): точка сохранена, но в аппроксимации не используется.</translation>
    </message>
    <message>
        <source>Point %1: %2 µm at ADC code %3 (mean of %4 samples).</source>
        <translation>Точка %1: %2 мкм при коде АЦП %3 (среднее по %4 отсчётам).</translation>
    </message>
    <message>
        <source>Point %1 read again: %2 µm at ADC code %3.</source>
        <translation>Точка %1 снята заново: %2 мкм при коде АЦП %3.</translation>
    </message>
    <message>
        <source>Typed point %1 added.</source>
        <translation>Точка %1 (вручную) добавлена.</translation>
    </message>
    <message>
        <source>Point %1 removed.</source>
        <translation>Точка %1 удалена.</translation>
    </message>
    <message>
        <source>The probe is not ready (%1): type the point instead.</source>
        <translation>Датчик не готов (%1): введите точку вручную.</translation>
    </message>
    <message>
        <source>No samples from the probe for %1 s. A mandrel withholds its samples while its ADC is over range (the bar bent beyond the probe&apos;s travel): unload the bar a little. Otherwise check its connection, or type the point.</source>
        <translation>Нет отсчётов от датчика в течение %1 с. Оправка не передаёт отсчёты, пока её АЦП за пределом диапазона (оправка изогнута сильнее хода датчика): немного разгрузите оправку. Иначе проверьте подключение или введите точку вручную.</translation>
    </message>
    <message>
        <source>The load changed while the point was read: capture it again once the bar is still.</source>
        <translation>Нагрузка изменилась во время снятия точки: снимите её заново, когда оправка успокоится.</translation>
    </message>
    <message>
        <source>Capture stopped; no point added.</source>
        <translation>Снятие остановлено; точка не добавлена.</translation>
    </message>
    <message>
        <source>the fit needs at least %1 points within the ADC&apos;s range, there are %2</source>
        <translation>для аппроксимации нужно не менее %1 точек в пределах диапазона АЦП, а их %2</translation>
    </message>
    <message>
        <source>the fit needs at least %1 different reference deflections, there are %2</source>
        <translation>для аппроксимации нужно не менее %1 различных эталонных прогибов, а их %2</translation>
    </message>
    <message>
        <source>the ADC code is %1 at every point: it does not follow the deflection (is the probe connected?)</source>
        <translation>код АЦП равен %1 во всех точках: он не следует за прогибом (датчик подключён?)</translation>
    </message>
    <message>
        <source>inside the calibrated range %1 to %2 µm</source>
        <translation>внутри калиброванного диапазона от %1 до %2 мкм</translation>
    </message>
    <message>
        <source>within the ADC&apos;s range 0 to %1, beyond the calibrated range</source>
        <translation>в пределах диапазона АЦП от 0 до %1, за калиброванным диапазоном</translation>
    </message>
    <message>
        <source>the fitted characteristic is not monotonic: it turns at %1 µm (ADC code %2) %3, so one code would stand for two deflections; check the points near there or choose another degree</source>
        <translation>аппроксимированная характеристика немонотонна: она поворачивает при %1 мкм (код АЦП %2) %3, и один код соответствовал бы двум прогибам; проверьте точки вблизи или выберите другую степень</translation>
    </message>
    <message>
        <source>the table does not fit the ADC&apos;s range 0 to %1 or 16-bit entries; calibrate over the whole travel of the probe</source>
        <translation>таблица не укладывается в диапазон АЦП от 0 до %1 или в 16-битные значения; калибруйте по всему ходу датчика</translation>
    </message>
    <message>
        <source>the points cannot be fitted (a value that is not a number, or a set-up out of range)</source>
        <translation>точки нельзя аппроксимировать (значение не является числом или настройка вне допустимого диапазона)</translation>
    </message>
    <message>
        <source>Degree %1, as chosen</source>
        <translation>Степень %1, как выбрано</translation>
    </message>
    <message>
        <source>Degree %1 chosen by cross-validation: it predicts the points best</source>
        <translation>Степень %1 выбрана перекрёстной проверкой: она лучше всего предсказывает точки</translation>
    </message>
    <message>
        <source>Degree %1 chosen by cross-validation: within one standard error of degree %2, which predicts best, so the simpler curve is kept</source>
        <translation>Степень %1 выбрана перекрёстной проверкой: в пределах одной стандартной ошибки от степени %2, которая предсказывает лучше всего, поэтому оставлена более простая кривая</translation>
    </message>
    <message>
        <source>Degree %1 chosen by cross-validation: within half an ADC code of degree %2, which predicts best, so the simpler curve is kept</source>
        <translation>Степень %1 выбрана перекрёстной проверкой: в пределах половины кода АЦП от степени %2, которая предсказывает лучше всего, поэтому оставлена более простая кривая</translation>
    </message>
    <message>
        <source>(only degrees up to %1 can be tried with %2 points)</source>
        <translation>(при %2 точках можно проверить только степени до %1)</translation>
    </message>
    <message>
        <source>Not used in the fit: point(s) %1, where the ADC saturated (a raw code reached 0 or %2). Capture them within the probe&apos;s range, or remove them.</source>
        <translation>Не используются в аппроксимации точки %1: там АЦП в насыщении (код достиг 0 или %2). Снимите их в пределах хода датчика или удалите.</translation>
    </message>
    <message>
        <source>Check at %1 µm: the ADC saturated (raw code %2 to %3), so the table cannot be verified there.</source>
        <translation>Проверка при %1 мкм: АЦП в насыщении (коды от %2 до %3), поэтому таблицу здесь проверить нельзя.</translation>
    </message>
    <message>
        <source>Check at %1 µm: the table reads %2 µm, %3 µm off (allowed ±%4 µm).</source>
        <translation>Проверка при %1 мкм: таблица показывает %2 мкм, отклонение %3 мкм (допускается ±%4 мкм).</translation>
    </message>
    <message>
        <source>Passed.</source>
        <translation>Пройдена.</translation>
    </message>
    <message>
        <source>Failed: capture more points or choose another degree.</source>
        <translation>Не пройдена: снимите больше точек или выберите другую степень.</translation>
    </message>
    <message>
        <source>Uploading…</source>
        <translation>Загрузка…</translation>
    </message>
    <message>
        <source>Stored; asking the mandrel which table it holds…</source>
        <translation>Записано; запрашиваем у оправки, какая таблица в ней хранится…</translation>
    </message>
    <message>
        <source>Verified: the mandrel reports version %1, %2, the same as the image sent.</source>
        <translation>Проверено: оправка сообщает версию %1, %2 — как у отправленного образа.</translation>
    </message>
    <message>
        <source>The mandrel did not report its table; upload again.</source>
        <translation>Оправка не сообщила данные своей таблицы; загрузите снова.</translation>
    </message>
    <message>
        <source>Upload again.</source>
        <translation>Загрузите снова.</translation>
    </message>
    <message>
        <source>Upload refused: %1</source>
        <translation>Загрузка отклонена: %1</translation>
    </message>
    <message>
        <source>Upload stopped. The saved table is kept; upload it again.</source>
        <translation>Загрузка остановлена. Сохранённая таблица не потеряна; загрузите её снова.</translation>
    </message>
    <message>
        <source>Upload failed: %1.</source>
        <translation>Загрузка не удалась: %1.</translation>
    </message>
    <message>
        <source>The saved table is kept; try again.</source>
        <translation>Сохранённая таблица не потеряна; повторите попытку.</translation>
    </message>
    <message>
        <source>Read-back does not match: the mandrel reports version %1, %2%3; the image has version %4, CRC-32C %5.</source>
        <translation>Контрольное считывание не совпадает: оправка сообщает версию %1, %2%3, а у образа версия %4, CRC-32C %5.</translation>
    </message>
    <message>
        <source>, and says the table is not valid</source>
        <translation> и считает таблицу недействительной</translation>
    </message>
    <message>
        <source>the forward and reverse strokes differ (taper or feed motion, not a dither)</source>
        <translation>прямой и обратный ходы различаются (конус или движение подачи, а не колебания)</translation>
    </message>
    <message>
        <source>the slide does not move: is the dither running?</source>
        <translation>суппорт не движется: включены ли колебания?</translation>
    </message>
    <message>
        <source>too few samples at constant velocity in each stroke: a longer dither period or faster polling is needed</source>
        <translation>слишком мало отсчётов при постоянной скорости в каждом ходе: нужен больший период колебаний или более частый опрос</translation>
    </message>
    <message>
        <source>too few complete forward and reverse strokes</source>
        <translation>слишком мало полных прямых и обратных ходов</translation>
    </message>
    <message>
        <source>%1 N: ΔI = %2 A from %3 stroke pairs.</source>
        <translation>%1 Н: ΔI = %2 А (пар ходов: %3).</translation>
    </message>
    <message>
        <source>Typed point added.</source>
        <translation>Точка, введённая вручную, добавлена.</translation>
    </message>
    <message>
        <source>Load %1 removed.</source>
        <translation>Нагрузка %1 удалена.</translation>
    </message>
    <message>
        <source>The drive read-out is not ready: %1</source>
        <translation>Датчик тока привода не готов: %1</translation>
    </message>
    <message>
        <source>No samples from the drive read-out for %1 s: check its connection.</source>
        <translation>Нет отсчётов от датчика тока привода в течение %1 с: проверьте подключение.</translation>
    </message>
    <message>
        <source>No reliable current difference at %1 N (%2 stroke pairs): %3</source>
        <translation>Нет надёжной разности токов при %1 Н (пар ходов: %2): %3</translation>
    </message>
    <message>
        <source>Measurement stopped; no point added.</source>
        <translation>Измерение остановлено; точка не добавлена.</translation>
    </message>
    <message>
        <source>k_p needs at least %1 known loads, there are %2</source>
        <translation>для k_p нужно не менее %1 известных нагрузок, а их %2</translation>
    </message>
    <message>
        <source>k_p needs at least 2 different loads</source>
        <translation>для k_p нужно не менее 2 различных нагрузок</translation>
    </message>
    <message>
        <source>load %1 is not a number</source>
        <translation>нагрузка %1 не является числом</translation>
    </message>
    <message>
        <source>the current difference is the same at every load: the drive current is not read</source>
        <translation>разность токов одинакова при всех нагрузках: ток привода не считывается</translation>
    </message>
    <message>
        <source>the current difference falls as the load grows (slope %1 N/A): the load acts the other way or the current sign is reversed</source>
        <translation>разность токов уменьшается с ростом нагрузки (наклон %1 Н/А): нагрузка приложена в обратную сторону или знак тока перепутан</translation>
    </message>
    <message>
        <source>Check at %1 N: k_p ΔI + offset gives %2 N, %3 N off (allowed ±%4 N).</source>
        <translation>Проверка при %1 Н: k_p ΔI + смещение даёт %2 Н, отклонение %3 Н (допускается ±%4 Н).</translation>
    </message>
    <message>
        <source>Failed: measure the loads again.</source>
        <translation>Не пройдена: измерьте нагрузки заново.</translation>
    </message>
</context>
<context>
    <name>SerialGauge</name>
    <message>
        <source>Readings</source>
        <translation>Показания</translation>
    </message>
    <message>
        <source>Sent with the DATA button</source>
        <translation>Передаются кнопкой DATA</translation>
    </message>
    <message>
        <source>Asked for by TrueTurn</source>
        <translation>Запрашиваются TrueTurn</translation>
    </message>
    <message>
        <source>Request string</source>
        <translation>Строка запроса</translation>
    </message>
    <message>
        <source>Sent to ask for a reading, as the interface&apos;s manual gives it; escapes \r \n \xNN.</source>
        <translation>Отправляется для запроса показания, как указано в руководстве к интерфейсу; escape-последовательности \r \n \xNN.</translation>
    </message>
    <message>
        <source>Reply timeout</source>
        <translation>Тайм-аут ответа</translation>
    </message>
    <message>
        <source>ms</source>
        <translation>мс</translation>
    </message>
    <message>
        <source>Request string: &apos;%1&apos; is empty or has a bad escape (use \r, \n, \xNN)</source>
        <translation>Строка запроса: «%1» пуста или содержит неверную escape-последовательность (используйте \r, \n, \xNN)</translation>
    </message>
    <message>
        <source>Serial data cable</source>
        <translation>Кабель данных (последовательный порт)</translation>
    </message>
    <message>
        <source>gauge</source>
        <translation>микрометр</translation>
    </message>
    <message>
        <source>%1 open; readings on request</source>
        <translation>%1 открыт; показания по запросу</translation>
    </message>
    <message>
        <source>%1 open; press DATA on the micrometer</source>
        <translation>%1 открыт; нажмите DATA на микрометре</translation>
    </message>
    <message>
        <source>opening %1</source>
        <translation>открытие %1</translation>
    </message>
    <message>
        <source>no answer from the gauge on %1 for %2 s</source>
        <translation>микрометр на %1 не отвечает %2 с</translation>
    </message>
    <message>
        <source>in</source>
        <translation>дюйм</translation>
    </message>
    <message>
        <source>mm</source>
        <translation>мм</translation>
    </message>
    <message>
        <source>Readings accepted</source>
        <translation>Принято показаний</translation>
    </message>
    <message>
        <source>Malformed frames</source>
        <translation>Искажённых кадров</translation>
    </message>
    <message>
        <source>Readings refused</source>
        <translation>Отклонено показаний</translation>
    </message>
    <message>
        <source>Bytes discarded</source>
        <translation>Отброшено байт</translation>
    </message>
    <message>
        <source>Requests unanswered</source>
        <translation>Запросов без ответа</translation>
    </message>
</context>
<context>
    <name>SerialLink</name>
    <message>
        <source>the port went away: cable or adapter unplugged</source>
        <translation>порт пропал: отключён кабель или адаптер</translation>
    </message>
    <message>
        <source>reading failed</source>
        <translation>ошибка чтения</translation>
    </message>
    <message>
        <source>writing failed</source>
        <translation>ошибка записи</translation>
    </message>
    <message>
        <source>the %1 on %2 was disconnected (%3)</source>
        <translation>%1 на %2: связь потеряна (%3)</translation>
    </message>
    <message>
        <source>cannot open %1 for the %2: %3</source>
        <translation>не удаётся открыть %1 (%2): %3</translation>
    </message>
    <message>
        <source>%1; reopening (%2)</source>
        <translation>%1; повторное открытие (%2)</translation>
    </message>
</context>
<context>
    <name>Simulator</name>
    <message>
        <source>the simulated gauge micrometer</source>
        <translation>симулятор микрометра</translation>
    </message>
    <message>
        <source>the simulated probe mandrel</source>
        <translation>симулятор оправки-датчика</translation>
    </message>
    <message>
        <source>the simulated drive-current readout</source>
        <translation>симулятор датчика тока привода</translation>
    </message>
    <message>
        <source>the simulated CNC output</source>
        <translation>симулятор выхода в ЧПУ</translation>
    </message>
    <message>
        <source>connecting to %1</source>
        <translation>подключение: %1</translation>
    </message>
    <message>
        <source>%1 is unplugged (fault switch)</source>
        <translation>%1 отключён (переключатель неисправностей)</translation>
    </message>
    <message>
        <source>reconnecting to %1</source>
        <translation>повторное подключение: %1</translation>
    </message>
    <message>
        <source>polling the simulated drive</source>
        <translation>опрос симулятора привода</translation>
    </message>
    <message>
        <source>no answer from the simulated drive for %1 polls</source>
        <translation>симулятор привода не отвечает (опросов: %1)</translation>
    </message>
    <message>
        <source>sample refused: %1</source>
        <translation>отсчёт отклонён: %1</translation>
    </message>
    <message>
        <source>%1 A, %2 mm/s, %3 mm</source>
        <translation>%1 А, %2 мм/с, %3 мм</translation>
    </message>
    <message>
        <source>Polls</source>
        <translation>Опросов</translation>
    </message>
    <message>
        <source>Samples refused</source>
        <translation>Отклонено отсчётов</translation>
    </message>
    <message>
        <source>simulated gauge ready</source>
        <translation>симулятор микрометра готов</translation>
    </message>
    <message>
        <source>%1 mm</source>
        <translation>%1 мм</translation>
    </message>
    <message>
        <source>no answer from the simulated gauge for %1 s</source>
        <translation>симулятор микрометра не отвечает %1 с</translation>
    </message>
    <message>
        <source>Readings accepted</source>
        <translation>Принято показаний</translation>
    </message>
    <message>
        <source>Malformed frames</source>
        <translation>Искажённых кадров</translation>
    </message>
    <message>
        <source>Readings refused</source>
        <translation>Отклонено показаний</translation>
    </message>
    <message>
        <source>the simulated CNC accepts corrections</source>
        <translation>симулятор ЧПУ принимает коррекции</translation>
    </message>
    <message>
        <source>read-back mismatch at value %1: wrote %2 mm, read %3 mm</source>
        <translation>контрольное считывание не совпадает для значения %1: записано %2 мм, считано %3 мм</translation>
    </message>
    <message>
        <source>%1 is not connected</source>
        <translation>%1 не подключён</translation>
    </message>
    <message>
        <source>no answer from %1</source>
        <translation>%1 не отвечает</translation>
    </message>
    <message>
        <source>part %1: the corrections do not match the control points</source>
        <translation>деталь %1: коррекции не соответствуют контрольным точкам</translation>
    </message>
    <message>
        <source>part %1: correction %2 mm is beyond the limit of %3 mm; nothing sent</source>
        <translation>деталь %1: коррекция %2 мм выходит за предел %3 мм; ничего не отправлено</translation>
    </message>
    <message>
        <source>part %1: %2 corrections verified</source>
        <translation>деталь %1: коррекции проверены (%2)</translation>
    </message>
    <message>
        <source>offset %1 mm is beyond the limit of %2 mm; nothing sent</source>
        <translation>смещение %1 мм выходит за предел %2 мм; ничего не отправлено</translation>
    </message>
    <message>
        <source>X offset %1 mm</source>
        <translation>смещение по X %1 мм</translation>
    </message>
    <message>
        <source>Writes</source>
        <translation>Записей</translation>
    </message>
    <message>
        <source>Refused or failed</source>
        <translation>Отклонено или с ошибкой</translation>
    </message>
    <message>
        <source>streaming</source>
        <translation>поток данных</translation>
    </message>
    <message>
        <source>starting the probe mandrel</source>
        <translation>запуск оправки-датчика</translation>
    </message>
    <message>
        <source>Simulator</source>
        <translation>Симулятор</translation>
    </message>
    <message>
        <source>Diameter measured</source>
        <translation>Измеряемый диаметр</translation>
    </message>
    <message>
        <source>mm</source>
        <translation>мм</translation>
    </message>
    <message>
        <source>Stand-alone: every reading is this diameter (plus noise when switched on).</source>
        <translation>Автономно: каждое показание равно этому диаметру (плюс шум, если он включён).</translation>
    </message>
    <message>
        <source>Resolution, decimals</source>
        <translation>Разрешение, знаков после запятой</translation>
    </message>
    <message>
        <source>3 = 0.001 mm, the micrometer of paper 000.</source>
        <translation>3 = 0.001 мм, как у микрометра в статье 000.</translation>
    </message>
    <message>
        <source>Reply timeout</source>
        <translation>Тайм-аут ответа</translation>
    </message>
    <message>
        <source>ms</source>
        <translation>мс</translation>
    </message>
    <message>
        <source>Sample rate</source>
        <translation>Частота отсчётов</translation>
    </message>
    <message>
        <source>Hz</source>
        <translation>Гц</translation>
    </message>
    <message>
        <source>Deflection, plane 1</source>
        <translation>Прогиб, плоскость 1</translation>
    </message>
    <message>
        <source>Stand-alone: constant bending of the bar.</source>
        <translation>Автономно: постоянный изгиб оправки.</translation>
    </message>
    <message>
        <source>Deflection, plane 2</source>
        <translation>Прогиб, плоскость 2</translation>
    </message>
    <message>
        <source>Silence timeout</source>
        <translation>Тайм-аут молчания</translation>
    </message>
    <message>
        <source>Polling period</source>
        <translation>Период опроса</translation>
    </message>
    <message>
        <source>Oscillation amplitude</source>
        <translation>Амплитуда колебаний</translation>
    </message>
    <message>
        <source>Paper 001: 0.005 to 0.05 mm, inside the tolerance.</source>
        <translation>Статья 001: от 0.005 до 0.05 мм, в пределах допуска.</translation>
    </message>
    <message>
        <source>Oscillation period</source>
        <translation>Период колебаний</translation>
    </message>
    <message>
        <source>s</source>
        <translation>с</translation>
    </message>
    <message>
        <source>Paper 001: 0.2 to 2 s.</source>
        <translation>Статья 001: от 0.2 до 2 с.</translation>
    </message>
    <message>
        <source>Friction current</source>
        <translation>Ток трения</translation>
    </message>
    <message>
        <source>A</source>
        <translation>А</translation>
    </message>
    <message>
        <source>Cutting current</source>
        <translation>Ток резания</translation>
    </message>
    <message>
        <source>Correction limit</source>
        <translation>Предел коррекции</translation>
    </message>
    <message>
        <source>Larger corrections are refused.</source>
        <translation>Большие коррекции отклоняются.</translation>
    </message>
    <message>
        <source>no data from %1 (silent)</source>
        <translation>нет данных: %1 молчит</translation>
    </message>
    <message>
        <source>Simulated lathe (built in)</source>
        <translation>Симулятор станка</translation>
    </message>
    <message>
        <source>Parts of the set-up are turned on the simulated lathe, measured at the control points and the next part is corrected.</source>
        <translation>детали наладки обтачиваются на симуляторе станка и измеряются в контрольных точках, а следующая деталь корректируется.</translation>
    </message>
    <message>
        <source>simulated CNC ready</source>
        <translation>симулятор ЧПУ готов</translation>
    </message>
    <message>
        <source>machining</source>
        <translation>идёт обработка</translation>
    </message>
    <message>
        <source>waiting for the next part</source>
        <translation>ожидание следующей детали</translation>
    </message>
    <message>
        <source>the simulated gauge does not answer</source>
        <translation>симулятор микрометра не отвечает</translation>
    </message>
    <message>
        <source>automatic measuring is off: diameters are entered by hand</source>
        <translation>автоматическое измерение выключено: диаметры вводятся вручную</translation>
    </message>
    <message>
        <source>simulated micrometer ready</source>
        <translation>симулятор микрометра готов</translation>
    </message>
    <message>
        <source>On a calibration stand</source>
        <translation>На калибровочном стенде</translation>
    </message>
    <message>
        <source>A screw jack bends the bar for the probe linearisation.</source>
        <translation>Винтовой домкрат изгибает оправку для линеаризации датчика.</translation>
    </message>
    <message>
        <source>A hydraulic jack applies the known loads of the k_p calibration.</source>
        <translation>Гидравлический домкрат создаёт известные нагрузки для калибровки k_p.</translation>
    </message>
</context>
<context>
    <name>tt::devices::DeviceManager</name>
    <message>
        <source>ready</source>
        <translation>готово</translation>
    </message>
    <message>
        <source>connecting</source>
        <translation>подключение</translation>
    </message>
    <message>
        <source>error</source>
        <translation>ошибка</translation>
    </message>
    <message>
        <source>closed</source>
        <translation>закрыто</translation>
    </message>
    <message>
        <source>plugin folder %1 does not exist</source>
        <translation>папка модулей %1 не существует</translation>
    </message>
    <message>
        <source>%1: not a TrueTurn device plugin</source>
        <translation>%1: не модуль устройств TrueTurn</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>%1: a plugin with id %2 is already loaded</source>
        <translation>%1: модуль с идентификатором %2 уже загружен</translation>
    </message>
    <message>
        <source>the device plugin %1 is not installed</source>
        <translation>модуль устройств %1 не установлен</translation>
    </message>
    <message>
        <source>the plugin %1 does not provide a %2</source>
        <translation>модуль %1 не поддерживает тип «%2»</translation>
    </message>
    <message>
        <source>no device with id %1</source>
        <translation>нет устройства с идентификатором %1</translation>
    </message>
    <message>
        <source> (%1 more in error)</source>
        <translation> (ещё с ошибкой: %1)</translation>
    </message>
    <message>
        <source>%1 of %2 ready; %3 %4</source>
        <translation>готово %1 из %2; %3: %4</translation>
    </message>
    <message numerus="yes">
        <source>%n ready</source>
        <translation>
            <numerusform>%n готово</numerusform>
            <numerusform>%n готовы</numerusform>
            <numerusform>%n готово</numerusform>
        </translation>
    </message>
    <message>
        <source>device %1: the saved entry is incomplete</source>
        <translation>устройство %1: сохранённая запись неполна</translation>
    </message>
</context>
<context>
    <name>tt::reports::ReportCharts</name>
    <message>
        <source>Individual diameters</source>
        <translation>Отдельные диаметры</translation>
    </message>
    <message>
        <source>Subgroup means</source>
        <translation>Средние подгрупп</translation>
    </message>
    <message>
        <source>part in order</source>
        <translation>деталь по порядку</translation>
    </message>
    <message>
        <source>subgroup</source>
        <translation>подгруппа</translation>
    </message>
    <message>
        <source>mm</source>
        <translation>мм</translation>
    </message>
    <message>
        <source>diameter, mm</source>
        <translation>диаметр, мм</translation>
    </message>
    <message>
        <source>diameter</source>
        <translation>диаметр</translation>
    </message>
    <message>
        <source>mean</source>
        <translation>среднее</translation>
    </message>
    <message>
        <source>centre line</source>
        <translation>центральная линия</translation>
    </message>
    <message>
        <source>control limits</source>
        <translation>контрольные границы</translation>
    </message>
    <message>
        <source>rule violations</source>
        <translation>нарушения правил</translation>
    </message>
    <message>
        <source>end of the baseline</source>
        <translation>конец базового периода</translation>
    </message>
    <message>
        <source>Subgroup ranges</source>
        <translation>Размахи подгрупп</translation>
    </message>
    <message>
        <source>Subgroup standard deviations</source>
        <translation>Стандартные отклонения подгрупп</translation>
    </message>
    <message>
        <source>Moving ranges</source>
        <translation>Скользящие размахи</translation>
    </message>
    <message>
        <source>spread, mm</source>
        <translation>разброс, мм</translation>
    </message>
    <message>
        <source>Distribution</source>
        <translation>Распределение</translation>
    </message>
    <message>
        <source>parts</source>
        <translation>детали</translation>
    </message>
    <message>
        <source>fitted normal</source>
        <translation>нормальное распределение</translation>
    </message>
    <message>
        <source>tolerance</source>
        <translation>допуск</translation>
    </message>
    <message>
        <source>nominal</source>
        <translation>номинал</translation>
    </message>
    <message>
        <source>x along the shaft, mm</source>
        <translation>x вдоль вала, мм</translation>
    </message>
    <message>
        <source>tolerance band</source>
        <translation>поле допуска</translation>
    </message>
    <message>
        <source>measured</source>
        <translation>измерено</translation>
    </message>
    <message>
        <source>Capability</source>
        <translation>Воспроизводимость</translation>
    </message>
    <message>
        <source>no tolerance stored</source>
        <translation>допуск не записан</translation>
    </message>
    <message>
        <source>Cp</source>
        <translation>Cp</translation>
    </message>
    <message>
        <source>Cpk</source>
        <translation>Cpk</translation>
    </message>
    <message>
        <source>Cpm</source>
        <translation>Cpm</translation>
    </message>
    <message>
        <source>Pp</source>
        <translation>Pp</translation>
    </message>
    <message>
        <source>Ppk</source>
        <translation>Ppk</translation>
    </message>
    <message>
        <source>Method</source>
        <translation>Метод</translation>
    </message>
    <message>
        <source>normal distribution</source>
        <translation>нормальное распределение</translation>
    </message>
    <message>
        <source>percentiles (ISO 22514-2)</source>
        <translation>процентили (ISO 22514-2)</translation>
    </message>
    <message>
        <source>Normality p (AD)</source>
        <translation>Нормальность p (AD)</translation>
    </message>
    <message>
        <source>σ within, mm</source>
        <translation>σ внутри подгрупп, мм</translation>
    </message>
    <message>
        <source>σ overall, mm</source>
        <translation>σ общая, мм</translation>
    </message>
    <message>
        <source>Mean, mm</source>
        <translation>Среднее, мм</translation>
    </message>
    <message>
        <source>Tolerance, mm</source>
        <translation>Допуск, мм</translation>
    </message>
    <message>
        <source>Point %1 at x = %2 mm</source>
        <translation>Точка %1 при x = %2 мм</translation>
    </message>
    <message numerus="yes">
        <source>%1 chart, limits from %n parts</source>
        <translation>
            <numerusform>Карта %1, границы по %n детали</numerusform>
            <numerusform>Карта %1, границы по %n деталям</numerusform>
            <numerusform>Карта %1, границы по %n деталям</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%1 chart of subgroups of %2, limits from %n subgroups</source>
        <translation>
            <numerusform>Карта %1 подгрупп по %2, границы по %n подгруппе</numerusform>
            <numerusform>Карта %1 подгрупп по %2, границы по %n подгруппам</numerusform>
            <numerusform>Карта %1 подгрупп по %2, границы по %n подгруппам</numerusform>
        </translation>
    </message>
    <message>
        <source>good %1 · rework %2 · scrap %3</source>
        <translation>годных %1 · доработка %2 · брак %3</translation>
    </message>
    <message numerus="yes">
        <source>… and %n more</source>
        <translation>
            <numerusform>… и ещё %n</numerusform>
            <numerusform>… и ещё %n</numerusform>
            <numerusform>… и ещё %n</numerusform>
        </translation>
    </message>
    <message>
        <source>%1: parts %2</source>
        <translation>%1: детали %2</translation>
    </message>
    <message>
        <source>controller changed</source>
        <translation>смена регулятора</translation>
    </message>
    <message>
        <source>EWMA fallback (weight %1)</source>
        <translation>резервный EWMA (вес %1)</translation>
    </message>
    <message>
        <source>proposed LQG applied%1</source>
        <translation>применён предложенный LQG%1</translation>
    </message>
    <message>
        <source>LQG refined%1</source>
        <translation>LQG уточнён%1</translation>
    </message>
    <message>
        <source>LQG adapted%1</source>
        <translation>LQG адаптирован%1</translation>
    </message>
    <message>
        <source>Run %1, part %2: %3</source>
        <translation>Серия %1, деталь %2: %3</translation>
    </message>
    <message>
        <source>, delay z = %1</source>
        <translation>, запазд. z = %1</translation>
    </message>
</context>
<context>
    <name>tt::reports::ReportPdf</name>
    <message>
        <source>Quality report</source>
        <translation>Отчёт о качестве</translation>
    </message>
    <message>
        <source>Machine: %1</source>
        <translation>Станок: %1</translation>
    </message>
    <message>
        <source>Job: %1</source>
        <translation>Задание: %1</translation>
    </message>
    <message>
        <source>Runs: %1</source>
        <translation>Серии: %1</translation>
    </message>
    <message>
        <source>Parts stored: %1</source>
        <translation>Детали записаны: %1</translation>
    </message>
    <message numerus="yes">
        <source>%n parts, %1</source>
        <translation>
            <numerusform>%n деталь, %1</numerusform>
            <numerusform>%n детали, %1</numerusform>
            <numerusform>%n деталей, %1</numerusform>
        </translation>
    </message>
    <message>
        <source>Printed %1 UTC</source>
        <translation>Напечатано %1 UTC</translation>
    </message>
    <message>
        <source>Point · x, mm · n · mean, mm · Cpk · Ppk · rule violations · good / rework / scrap</source>
        <translation>Точка · x, мм · n · среднее, мм · Cpk · Ppk · нарушения правил · годных / доработка / брак</translation>
    </message>
    <message>
        <source>Checked by: ______________________   Date: ____________   Signature: ______________________</source>
        <translation>Проверил: ______________________   Дата: ____________   Подпись: ______________________</translation>
    </message>
    <message>
        <source>machine %1, job %2</source>
        <translation>станок %1, задание %2</translation>
    </message>
    <message numerus="yes">
        <source>Rule violations (Western Electric): %n</source>
        <translation>
            <numerusform>Нарушения правил (WE): %n</numerusform>
            <numerusform>Нарушения правил (WE): %n</numerusform>
            <numerusform>Нарушения правил (WE): %n</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Controller changes of the adaptive loop (marked on the chart): %n</source>
        <translation>
            <numerusform>Смены регулятора адаптивного контура (отмечены на карте): %n</numerusform>
            <numerusform>Смены регулятора адаптивного контура (отмечены на карте): %n</numerusform>
            <numerusform>Смены регулятора адаптивного контура (отмечены на карте): %n</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>tt::runtime::BoringTargets</name>
    <message>
        <source>Station&apos;s PLC</source>
        <translation>ПЛК стенда</translation>
    </message>
    <message>
        <source>The simulated pass cannot begin: its scenario or its mandrel&apos;s calibration is refused.</source>
        <translation>Симулированный проход не может начаться: его сценарий или калибровка оправки отклонены.</translation>
    </message>
    <message>
        <source>The chosen CNC output is gone.</source>
        <translation>Выбранного выхода в ЧПУ больше нет.</translation>
    </message>
    <message>
        <source>No devices are configured.</source>
        <translation>Устройства не настроены.</translation>
    </message>
</context>
<context>
    <name>tt::runtime::DeviceHost</name>
    <message>
        <source>TrueTurn is closing</source>
        <translation>TrueTurn закрывается</translation>
    </message>
    <message>
        <source>the device plugin %1 is not installed</source>
        <translation>модуль устройств %1 не установлен</translation>
    </message>
    <message>
        <source>this source runs no boring pass of its own</source>
        <translation>у этого источника нет собственного прохода расточки</translation>
    </message>
    <message>
        <source>the CNC output is no longer on the Devices page</source>
        <translation>выхода на ЧПУ больше нет на странице «Устройства»</translation>
    </message>
    <message>
        <source>this instrument is not on a calibration stand</source>
        <translation>этот прибор не стоит на калибровочном стенде</translation>
    </message>
    <message>
        <source>this stand has no screw jack</source>
        <translation>у этого стенда нет винтового домкрата</translation>
    </message>
    <message>
        <source>this stand has no hydraulic jack</source>
        <translation>у этого стенда нет гидравлического домкрата</translation>
    </message>
    <message>
        <source>this probe cannot take a table upload</source>
        <translation>в эту оправку нельзя загрузить таблицу</translation>
    </message>
</context>
<context>
    <name>tt::runtime::DeviceHub</name>
    <message>
        <source>ready</source>
        <translation>готов</translation>
    </message>
    <message>
        <source>connecting</source>
        <translation>подключается</translation>
    </message>
    <message>
        <source>error</source>
        <translation>ошибка</translation>
    </message>
    <message>
        <source>closed</source>
        <translation>закрыт</translation>
    </message>
    <message>
        <source> (%1 more in error)</source>
        <translation> (ещё с ошибкой: %1)</translation>
    </message>
    <message>
        <source>%1 of %2 ready; %3 %4</source>
        <translation>готово %1 из %2; %3: %4</translation>
    </message>
    <message numerus="yes">
        <source>%n ready</source>
        <translation>
            <numerusform>%n готово</numerusform>
            <numerusform>%n готовы</numerusform>
            <numerusform>%n готово</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>tt::runtime::LatheLink</name>
    <message>
        <source>the %1 “%2” is no longer on the Devices page</source>
        <translation>%1 «%2» удалён со страницы «Устройства»</translation>
    </message>
    <message>
        <source>the Run page was closed</source>
        <translation>страница «Работа» закрыта</translation>
    </message>
    <message>
        <source>a new run was started</source>
        <translation>начата новая серия</translation>
    </message>
    <message>
        <source>gauge</source>
        <translation>микрометр</translation>
    </message>
    <message>
        <source>CNC output</source>
        <translation>Выход в ЧПУ</translation>
    </message>
</context>
<context>
    <name>tt::runtime::LoopWorker</name>
    <message>
        <source>A run is already going; stop it first.</source>
        <translation>Серия уже выполняется; сначала остановите её.</translation>
    </message>
    <message>
        <source>The run history cannot be opened: %1</source>
        <translation>Не удаётся открыть историю серий: %1</translation>
    </message>
    <message>
        <source>The run cannot start: the CNC output “%1” writes programs for a diameter of %2 mm, the set-up %3 turns %4 mm; correct the nominal diameter on the Devices page or choose another set-up</source>
        <translation>Запуск невозможен: выход ЧПУ «%1» пишет программы для диаметра %2 мм, а наладка %3 обтачивает %4 мм; исправьте номинальный диаметр на странице «Устройства» или выберите другую наладку</translation>
    </message>
    <message>
        <source>The run cannot start: %1</source>
        <translation>Серию невозможно запустить: %1</translation>
    </message>
    <message numerus="yes">
        <source>%n gauge reading(s) taken while the diameters were typed by hand were not used.</source>
        <translation>
            <numerusform>%n показание микрометра, снятое во время ручного ввода диаметров, не использовано.</numerusform>
            <numerusform>%n показания микрометра, снятые во время ручного ввода диаметров, не использованы.</numerusform>
            <numerusform>%n показаний микрометра, снятых во время ручного ввода диаметров, не использованы.</numerusform>
        </translation>
    </message>
    <message>
        <source>No run is going: the diameters were not taken.</source>
        <translation>Серия не выполняется: диаметры не приняты.</translation>
    </message>
    <message>
        <source>Part %1 is not the part waiting for its diameters; nothing was taken.</source>
        <translation>Деталь %1 не ожидает ввода диаметров; ничего не принято.</translation>
    </message>
    <message>
        <source>No part is on the machine.</source>
        <translation>На станке нет детали.</translation>
    </message>
    <message>
        <source>The new controller tuning was not taken: %1</source>
        <translation>Новая настройка регулятора не принята: %1</translation>
    </message>
</context>
<context>
    <name>tt::runtime::MachineCatalog</name>
    <message>
        <source>Real lathe (Devices page)</source>
        <translation>Реальный станок</translation>
    </message>
    <message>
        <source>each part&apos;s corrections go to the CNC; you machine the part and press Part finished.</source>
        <translation>коррекции каждой детали уходят в ЧПУ; вы обрабатываете деталь и нажимаете «Деталь готова».</translation>
    </message>
    <message>
        <source>ready</source>
        <translation>готов</translation>
    </message>
    <message>
        <source>still connecting</source>
        <translation>ещё подключается</translation>
    </message>
    <message>
        <source>closed</source>
        <translation>закрыт</translation>
    </message>
    <message>
        <source>in error</source>
        <translation>в состоянии ошибки</translation>
    </message>
    <message>
        <source>No CNC output is chosen. Add a G-code file or Modbus correction output on the Devices page and choose it under CNC output.</source>
        <translation>Выход в ЧПУ не выбран. Добавьте выход коррекции (файл G-кода или Modbus) на странице «Устройства» и выберите его в поле «Выход в ЧПУ».</translation>
    </message>
    <message>
        <source>The CNC output chosen is no longer on the Devices page; choose another.</source>
        <translation>Выбранного выхода в ЧПУ больше нет на странице «Устройства»; выберите другой.</translation>
    </message>
    <message>
        <source>The CNC output “%1” is %2: %3. Check it on the Devices page.</source>
        <translation>Выход в ЧПУ «%1» %2: %3. Проверьте его на странице «Устройства».</translation>
    </message>
    <message>
        <source>The gauge chosen is no longer on the Devices page; choose another or type the diameters by hand.</source>
        <translation>Выбранного микрометра больше нет на странице «Устройства»; выберите другой или вводите диаметры вручную.</translation>
    </message>
    <message>
        <source>The gauge “%1” is %2: %3. Check it on the Devices page, or choose to type the diameters by hand.</source>
        <translation>Микрометр «%1» %2: %3. Проверьте его на странице «Устройства» или выберите ручной ввод диаметров.</translation>
    </message>
</context>
<context>
    <name>tt::runtime::TerminalDevices</name>
    <message>
        <source>Simulated gauge micrometer</source>
        <translation>Симулятор микрометра</translation>
    </message>
    <message>
        <source>Simulated probe mandrel</source>
        <translation>Симулятор оправки-датчика</translation>
    </message>
    <message>
        <source>Simulated drive-current readout</source>
        <translation>Симулятор датчика тока привода</translation>
    </message>
    <message>
        <source>Simulated CNC output</source>
        <translation>Симулятор выхода в ЧПУ</translation>
    </message>
</context>
<context>
    <name>tt::ui</name>
    <message>
        <source>Plant database offline since %1; parts kept on this terminal: %2</source>
        <translation>Заводская база данных недоступна с %1; деталей хранится на этом терминале: %2</translation>
    </message>
    <message>
        <source>Plant database: connecting; parts kept on this terminal: %1</source>
        <translation>Заводская база данных: подключение; деталей хранится на этом терминале: %1</translation>
    </message>
    <message>
        <source>Plant database: every part sent</source>
        <translation>Заводская база данных: все детали переданы</translation>
    </message>
    <message>
        <source>Plant database: sending; parts kept on this terminal: %1</source>
        <translation>Заводская база данных: передача; деталей хранится на этом терминале: %1</translation>
    </message>
    <message>
        <source>%1. The journal on this terminal is full (%2 of %3 MiB): the loop takes no new part until the plant database has taken parts</source>
        <translation>%1. Журнал на этом терминале заполнен (%2 из %3 МиБ): цикл не берёт новую деталь, пока заводская база данных не примет детали</translation>
    </message>
    <message>
        <source>%1. The journal on this terminal is nearly full (%2 of %3 MiB)</source>
        <translation>%1. Журнал на этом терминале почти заполнен (%2 из %3 МиБ)</translation>
    </message>
</context>
<context>
    <name>tt::ui::About</name>
    <message>
        <source>Run-to-run LQG control of the shaft profile</source>
        <translation>LQG-управление профилем вала от детали к детали</translation>
    </message>
    <message>
        <source>In-process compensation of boring-bar deflection</source>
        <translation>Компенсация прогиба расточной оправки в процессе обработки</translation>
    </message>
    <message>
        <source>Feed scheduling against force deformation, with G-code</source>
        <translation>Программирование подачи против силовых деформаций, с G-кодом</translation>
    </message>
    <message>
        <source>Neural corrective pulse of the feed drives at corners</source>
        <translation>Нейросетевой корректирующий импульс приводов подачи на углах</translation>
    </message>
    <message>
        <source>Hydraulic feed stabilisation</source>
        <translation>Стабилизация гидравлической подачи</translation>
    </message>
    <message>
        <source>Calibration of the probe and the gauge, tool stiffness table</source>
        <translation>Калибровка датчика и скобы, таблица жёсткости инструмента</translation>
    </message>
    <message>
        <source>Devices: gauge, probe mandrel, Modbus, CNC correction output</source>
        <translation>Устройства: скоба, оправка, Modbus, коррекция в ЧПУ</translation>
    </message>
    <message>
        <source>Run history (SQLite, PostgreSQL), SPC figures (report command)</source>
        <translation>История (SQLite, PostgreSQL), показатели SPC (команда report)</translation>
    </message>
    <message>
        <source>The Reports page and PDF reports</source>
        <translation>Страница «Отчёты» и отчёты в PDF</translation>
    </message>
    <message>
        <source>&lt;h2&gt;TrueTurn %1&lt;/h2&gt;&lt;p&gt;Adaptive accuracy control for lathes.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Implemented:&lt;/b&gt;&lt;/p&gt;%2&lt;p&gt;&lt;b&gt;Not yet implemented:&lt;/b&gt;&lt;/p&gt;%3&lt;p&gt;Qt %4&lt;/p&gt;&lt;p&gt;Log file: %5&lt;/p&gt;</source>
        <translation>&lt;h2&gt;TrueTurn %1&lt;/h2&gt;&lt;p&gt;Адаптивное управление точностью токарной обработки.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Реализовано:&lt;/b&gt;&lt;/p&gt;%2&lt;p&gt;&lt;b&gt;Пока не реализовано:&lt;/b&gt;&lt;/p&gt;%3&lt;p&gt;Qt %4&lt;/p&gt;&lt;p&gt;Файл журнала: %5&lt;/p&gt;</translation>
    </message>
    <message>
        <source>not written</source>
        <translation>не ведётся</translation>
    </message>
    <message>
        <source>The Controller page: tuning with live predictions and margins</source>
        <translation>Страница регулятора: настройка с прогнозом и запасами</translation>
    </message>
    <message>
        <source>Integral action, double EWMA and model-mismatch detection</source>
        <translation>Интегральное действие, двойной EWMA, контроль модели</translation>
    </message>
    <message>
        <source>ARMA identification of the disturbance from the history</source>
        <translation>Идентификация ARMA-модели возмущения по истории</translation>
    </message>
    <message>
        <source>Users, roles, log-in and the audit trail</source>
        <translation>Пользователи, роли, вход и журнал изменений</translation>
    </message>
    <message>
        <source>Kiosk mode and an on-screen keypad</source>
        <translation>Режим киоска и экранная клавиатура</translation>
    </message>
    <message>
        <source>One run request for the Run page, CLI and resume</source>
        <translation>Один запрос прогона: страница «Работа», CLI, продолжение</translation>
    </message>
    <message>
        <source>Devices in a thread of their own</source>
        <translation>Устройства в собственном потоке</translation>
    </message>
    <message>
        <source>The LinuxCNC lathe on the Run page and in simulate</source>
        <translation>Станок LinuxCNC на странице «Работа» и в simulate</translation>
    </message>
    <message>
        <source>Plant-wide history: a journal on each terminal, the Plant page</source>
        <translation>История цеха: журнал на каждом терминале, страница «Цех»</translation>
    </message>
    <message>
        <source>Retraining of the corrective pulse on drive drifts</source>
        <translation>Переобучение корректирующего импульса при дрейфе приводов</translation>
    </message>
    <message>
        <source>Adaptive control: a robust fallback and a new design on a mismatch</source>
        <translation>Адаптивное управление: резервный регулятор и новый расчёт</translation>
    </message>
    <message>
        <source>The controller&apos;s changes on the Reports page&apos;s control chart</source>
        <translation>Смены регулятора на контрольной карте отчётов</translation>
    </message>
    <message>
        <source>Adapting to the tool&apos;s wear and the lathe&apos;s warm-up</source>
        <translation>Адаптация к износу резца и прогреву станка</translation>
    </message>
</context>
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
    <name>tt::ui::AuditDialog</name>
    <message>
        <source>Setting</source>
        <translation>Настройка</translation>
    </message>
    <message>
        <source>Calibration</source>
        <translation>Калибровка</translation>
    </message>
    <message>
        <source>Tool</source>
        <translation>Инструмент</translation>
    </message>
    <message>
        <source>User</source>
        <translation>Пользователь</translation>
    </message>
    <message>
        <source>Controller</source>
        <translation>Регулятор</translation>
    </message>
    <message>
        <source>Log-in</source>
        <translation>Вход</translation>
    </message>
    <message>
        <source>Audit trail</source>
        <translation>Журнал аудита</translation>
    </message>
    <message>
        <source>All changes</source>
        <translation>Все изменения</translation>
    </message>
    <message>
        <source>Filter: name, tool, field or value</source>
        <translation>Фильтр: имя, инструмент, поле или значение</translation>
    </message>
    <message>
        <source>When</source>
        <translation>Когда</translation>
    </message>
    <message>
        <source>Who</source>
        <translation>Кто</translation>
    </message>
    <message>
        <source>Role</source>
        <translation>Роль</translation>
    </message>
    <message>
        <source>What</source>
        <translation>Что</translation>
    </message>
    <message>
        <source>Subject</source>
        <translation>Объект</translation>
    </message>
    <message>
        <source>Field</source>
        <translation>Поле</translation>
    </message>
    <message>
        <source>Old value</source>
        <translation>Было</translation>
    </message>
    <message>
        <source>New value</source>
        <translation>Стало</translation>
    </message>
    <message>
        <source>Export CSV…</source>
        <translation>Экспорт CSV…</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>Закрыть</translation>
    </message>
    <message>
        <source>Show</source>
        <translation>Показать</translation>
    </message>
    <message>
        <source>The database cannot be opened: %1</source>
        <translation>Не удаётся открыть базу данных: %1</translation>
    </message>
    <message>
        <source>Not shown: %1</source>
        <translation>Не показано: %1</translation>
    </message>
    <message numerus="yes">
        <source>%n record(s)</source>
        <translation>
            <numerusform>%n запись</numerusform>
            <numerusform>%n записи</numerusform>
            <numerusform>%n записей</numerusform>
        </translation>
    </message>
    <message>
        <source>Export the audit trail</source>
        <translation>Экспорт журнала аудита</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>Файлы CSV (*.csv)</translation>
    </message>
    <message>
        <source>Not written: %1 (%2)</source>
        <translation>Не записано: %1 (%2)</translation>
    </message>
    <message numerus="yes">
        <source>%n record(s) written to %1</source>
        <translation>
            <numerusform>%n запись записана в %1</numerusform>
            <numerusform>%n записи записаны в %1</numerusform>
            <numerusform>%n записей записано в %1</numerusform>
        </translation>
    </message>
    <message>
        <source>logged in</source>
        <translation>вход выполнен</translation>
    </message>
    <message>
        <source>password set</source>
        <translation>пароль задан</translation>
    </message>
    <message>
        <source>PIN set</source>
        <translation>PIN задан</translation>
    </message>
    <message>
        <source>unlocked</source>
        <translation>разблокирован</translation>
    </message>
    <message>
        <source>user %1</source>
        <translation>пользователь %1</translation>
    </message>
    <message numerus="yes">
        <source>Hash chain intact: %n row(s) checked.</source>
        <translation>
            <numerusform>Цепочка хешей цела: проверена %n строка.</numerusform>
            <numerusform>Цепочка хешей цела: проверены %n строки.</numerusform>
            <numerusform>Цепочка хешей цела: проверено %n строк.</numerusform>
        </translation>
    </message>
    <message>
        <source>row %1 edited</source>
        <translation>строка %1 изменена</translation>
    </message>
    <message>
        <source>row %1 inserted</source>
        <translation>строка %1 вставлена</translation>
    </message>
    <message>
        <source>the chain&apos;s head does not match its last row</source>
        <translation>голова цепочки не совпадает с её последней строкой</translation>
    </message>
    <message numerus="yes">
        <source>%n row(s) deleted before row %1</source>
        <translation>
            <numerusform>%n строка удалена перед строкой %1</numerusform>
            <numerusform>%n строки удалены перед строкой %1</numerusform>
            <numerusform>%n строк удалено перед строкой %1</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n row(s) deleted at the end</source>
        <translation>
            <numerusform>%n строка удалена в конце</numerusform>
            <numerusform>%n строки удалены в конце</numerusform>
            <numerusform>%n строк удалено в конце</numerusform>
        </translation>
    </message>
    <message>
        <source>Hash chain BROKEN: the trail was changed outside TrueTurn (%1).</source>
        <translation>Цепочка хешей НАРУШЕНА: журнал изменён в обход TrueTurn (%1).</translation>
    </message>
    <message>
        <source>Hash chain not checked: %1</source>
        <translation>Цепочка хешей не проверена: %1</translation>
    </message>
</context>
<context>
    <name>tt::ui::BoringPanel</name>
    <message>
        <source>The devices were changed, so the compensation stopped. The CNC keeps the offset it holds.</source>
        <translation>Устройства изменены, поэтому компенсация остановлена. ЧПУ сохраняет текущее смещение.</translation>
    </message>
    <message>
        <source>The chosen source device is gone.</source>
        <translation>Выбранного устройства-источника больше нет.</translation>
    </message>
    <message>
        <source>No CNC output for the dynamic X offset: add one on the Devices page.</source>
        <translation>Нет выхода в ЧПУ для динамического смещения по X: добавьте его на странице «Устройства».</translation>
    </message>
    <message>
        <source>Choose where the deflection comes from.</source>
        <translation>Выберите источник прогиба.</translation>
    </message>
    <message>
        <source>No tool: add the boring bar to the tool table on the Tools page.</source>
        <translation>Нет инструмента: добавьте расточную оправку в таблицу инструментов на странице «Инструменты».</translation>
    </message>
    <message>
        <source>Choose the tool.</source>
        <translation>Выберите инструмент.</translation>
    </message>
    <message>
        <source>Cannot start: %1</source>
        <translation>Пуск невозможен: %1</translation>
    </message>
    <message>
        <source>Starting</source>
        <translation>Запуск</translation>
    </message>
    <message>
        <source>Stopped</source>
        <translation>Остановлено</translation>
    </message>
    <message>
        <source>Zero the offset</source>
        <translation>Обнулить смещение</translation>
    </message>
    <message>
        <source>The CNC holds a dynamic X offset of %1 mm. Set it to 0 now? The tool moves by %2 mm: do this only with the tool out of the bore.</source>
        <translation>В ЧПУ установлено динамическое смещение по X %1 мм. Обнулить его сейчас? Инструмент переместится на %2 мм: делайте это только с инструментом, выведенным из отверстия.</translation>
    </message>
    <message>
        <source>The CNC did not take the offset 0: %1</source>
        <translation>ЧПУ не приняло нулевое смещение: %1</translation>
    </message>
    <message>
        <source>The bore is finished: largest diameter error %1 mm with compensation, %2 mm without (%3 %).</source>
        <translation>Отверстие расточено: наибольшая погрешность диаметра %1 мм с компенсацией, %2 мм без неё (%3 %).</translation>
    </message>
    <message>
        <source>Holding</source>
        <translation>Удержание</translation>
    </message>
    <message>
        <source>Offset %1 mm</source>
        <translation>Смещение %1 мм</translation>
    </message>
    <message>
        <source>Deflection %1 mm</source>
        <translation>Прогиб %1 мм</translation>
    </message>
    <message>
        <source>Deflection —</source>
        <translation>Прогиб —</translation>
    </message>
    <message>
        <source>Force %1 N</source>
        <translation>Сила %1 Н</translation>
    </message>
    <message>
        <source>Force —</source>
        <translation>Сила —</translation>
    </message>
    <message>
        <source>Stopped. The CNC keeps the offset it holds. Choose the source, the tool and the limits, then Start.</source>
        <translation>Остановлено. ЧПУ сохраняет текущее смещение. Выберите источник, инструмент и пределы, затем нажмите «Пуск».</translation>
    </message>
    <message>
        <source>Bore diameter error from %1 mm in: %2 mm with compensation, %3 mm without</source>
        <translation>Погрешность диаметра отверстия начиная с %1 мм от входа: %2 мм с компенсацией, %3 мм без неё</translation>
    </message>
    <message>
        <source>Bore diameter error: shown from %1 mm into the bore</source>
        <translation>Погрешность диаметра отверстия: показана начиная с %1 мм от входа</translation>
    </message>
    <message>
        <source>Tool at %1 of %2 mm</source>
        <translation>Инструмент на %1 из %2 мм</translation>
    </message>
    <message>
        <source>Offset applied</source>
        <translation>Смещение</translation>
    </message>
    <message>
        <source>Without compensation</source>
        <translation>Без компенсации</translation>
    </message>
    <message>
        <source>With compensation</source>
        <translation>С компенсацией</translation>
    </message>
    <message>
        <source>Set-up</source>
        <translation>Наладка</translation>
    </message>
    <message>
        <source>Source</source>
        <translation>Источник</translation>
    </message>
    <message>
        <source>Plane along X</source>
        <translation>Плоскость по X</translation>
    </message>
    <message>
        <source>Tool</source>
        <translation>Инструмент</translation>
    </message>
    <message>
        <source>CNC output</source>
        <translation>Выход в ЧПУ</translation>
    </message>
    <message>
        <source>Offset limit ±</source>
        <translation>Предел смещения ±</translation>
    </message>
    <message>
        <source>Rate limit</source>
        <translation>Предел скорости</translation>
    </message>
    <message>
        <source>PLC cycle</source>
        <translation>Цикл ПЛК</translation>
    </message>
    <message>
        <source>Cutting</source>
        <translation>Обработка</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Скорость</translation>
    </message>
    <message>
        <source>Simulate a silent read-out</source>
        <translation>Имитация: датчик молчит</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Пуск</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Стоп</translation>
    </message>
    <message>
        <source>Zero the offset…</source>
        <translation>Обнулить смещение…</translation>
    </message>
    <message>
        <source>Plane 1</source>
        <translation>Плоскость 1</translation>
    </message>
    <message>
        <source>Plane 2</source>
        <translation>Плоскость 2</translation>
    </message>
    <message>
        <source>Cylinder</source>
        <translation>Цилиндр</translation>
    </message>
    <message>
        <source>Taper</source>
        <translation>Конус</translation>
    </message>
    <message>
        <source>Contour</source>
        <translation>Контур</translation>
    </message>
    <message>
        <source>%1: probe mandrel</source>
        <translation>%1: оправка-датчик</translation>
    </message>
    <message>
        <source>%1: current + dither</source>
        <translation>%1: ток + дизеринг</translation>
    </message>
    <message>
        <source>Station: %1</source>
        <translation>Стенд: %1</translation>
    </message>
    <message>
        <source>k %1 N/mm%2 · k_p %3 N/A
L/d %4</source>
        <translation>k %1 Н/мм%2 · k_p %3 Н/А
L/d %4</translation>
    </message>
    <message>
        <source> (measured)</source>
        <translation> (измерено)</translation>
    </message>
    <message>
        <source>not calibrated</source>
        <translation>не откалиброван</translation>
    </message>
    <message>
        <source>The tool table cannot be read: %1</source>
        <translation>Не удаётся прочитать таблицу инструментов: %1</translation>
    </message>
    <message>
        <source>No tool in the tool table (Tools page).</source>
        <translation>В таблице инструментов нет ни одного инструмента (страница «Инструменты»).</translation>
    </message>
    <message>
        <source>Deflection and dynamic X offset</source>
        <translation>Прогиб и динамическое смещение по X</translation>
    </message>
    <message>
        <source>Time, s</source>
        <translation>Время, с</translation>
    </message>
    <message>
        <source>mm</source>
        <translation>мм</translation>
    </message>
    <message>
        <source>Bore diameter error along the bore (simulated station)</source>
        <translation>Погрешность Ø по длине отверстия (симулятор)</translation>
    </message>
    <message>
        <source>Position in the bore, mm</source>
        <translation>Положение в отверстии, мм</translation>
    </message>
    <message>
        <source>Diameter error, mm</source>
        <translation>Ошибка Ø, мм</translation>
    </message>
    <message>
        <source> mm</source>
        <translation> мм</translation>
    </message>
    <message>
        <source> mm/s</source>
        <translation> мм/с</translation>
    </message>
    <message>
        <source> ms</source>
        <translation> мс</translation>
    </message>
    <message>
        <source>Measured</source>
        <translation>Измеренный</translation>
    </message>
    <message>
        <source>Real (simulator)</source>
        <translation>Истинный</translation>
    </message>
    <message>
        <source>boring bar: %1</source>
        <translation>расточная оправка: %1</translation>
    </message>
</context>
<context>
    <name>tt::ui::CalibrationPage</name>
    <message>
        <source>The devices changed while a calibration was open, so it was closed; the captured points are kept. Open it again to continue.</source>
        <translation>Во время калибровки изменились устройства, поэтому она закрыта; снятые точки сохранены. Откройте её снова, чтобы продолжить.</translation>
    </message>
    <message>
        <source>Start over</source>
        <translation>Начать заново</translation>
    </message>
    <message>
        <source>Forget the %1 captured points of the unfinished calibration?</source>
        <translation>Удалить снятые точки незавершённой калибровки (%1)?</translation>
    </message>
    <message>
        <source>not uploaded</source>
        <translation>не загружена</translation>
    </message>
    <message>
        <source>verified, CRC %1</source>
        <translation>проверена, CRC %1</translation>
    </message>
    <message>
        <source>read-back CRC %1 does not match</source>
        <translation>CRC %1 при контрольном считывании не совпадает</translation>
    </message>
    <message>
        <source>Probe mandrel linearisation</source>
        <translation>Линеаризация оправки-датчика</translation>
    </message>
    <message>
        <source>Builds the table ADC code → deflection that the mandrel&apos;s microcontroller uses: capture points against a dial indicator, fit the sensor&apos;s characteristic, save a new table version and upload it with read-back of its CRC.</source>
        <translation>Строит таблицу «код АЦП → прогиб» для микроконтроллера оправки: снимите точки по индикатору часового типа, аппроксимируйте характеристику датчика, сохраните новую версию таблицы и загрузите её с контрольным считыванием CRC.</translation>
    </message>
    <message>
        <source>Continue the calibration (%1 points kept)…</source>
        <translation>Продолжить калибровку (сохранено точек: %1)…</translation>
    </message>
    <message>
        <source>Linearise a probe mandrel…</source>
        <translation>Линеаризовать оправку-датчик…</translation>
    </message>
    <message>
        <source>Probe</source>
        <translation>Оправка</translation>
    </message>
    <message>
        <source>Plane</source>
        <translation>Плоскость</translation>
    </message>
    <message>
        <source>Version</source>
        <translation>Версия</translation>
    </message>
    <message>
        <source>Saved</source>
        <translation>Сохранена</translation>
    </message>
    <message>
        <source>By</source>
        <translation>Кем</translation>
    </message>
    <message>
        <source>Degree</source>
        <translation>Степень</translation>
    </message>
    <message>
        <source>Table error, µm</source>
        <translation>Погрешность таблицы, мкм</translation>
    </message>
    <message>
        <source>In the mandrel</source>
        <translation>В оправке</translation>
    </message>
    <message>
        <source>Current-to-force gain k_p</source>
        <translation>Коэффициент ток–сила k_p</translation>
    </message>
    <message>
        <source>Known loads on the cross slide against the motor current difference with dither; the result is written into the tool table.</source>
        <translation>Известные нагрузки на поперечный суппорт сопоставляются с разностью тока двигателя при дизеринге; результат записывается в таблицу инструментов.</translation>
    </message>
    <message>
        <source>Calibrate k_p from known loads…</source>
        <translation>Калибровать k_p по известным нагрузкам…</translation>
    </message>
    <message>
        <source>When</source>
        <translation>Когда</translation>
    </message>
    <message>
        <source>Drive</source>
        <translation>Привод</translation>
    </message>
    <message>
        <source>k_p, N/A</source>
        <translation>k_p, Н/А</translation>
    </message>
    <message>
        <source>R²</source>
        <translation>R²</translation>
    </message>
    <message>
        <source>Tools</source>
        <translation>Инструменты</translation>
    </message>
    <message>
        <source>The calibration database cannot be opened: %1. Tables can still be built and exported, not saved.</source>
        <translation>Не удаётся открыть базу калибровок: %1. Таблицы можно строить и экспортировать, но не сохранять.</translation>
    </message>
</context>
<context>
    <name>tt::ui::CalibrationWizard</name>
    <message>
        <source>&lt; Back</source>
        <translation>&lt; Назад</translation>
    </message>
    <message>
        <source>Next &gt;</source>
        <translation>Далее &gt;</translation>
    </message>
    <message>
        <source>Finish</source>
        <translation>Готово</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Отмена</translation>
    </message>
</context>
<context>
    <name>tt::ui::ControllerPage</name>
    <message>
        <source>Controller</source>
        <translation>Регулятор</translation>
    </message>
    <message>
        <source>Delay z, parts</source>
        <translation>Задержка z, дет.</translation>
    </message>
    <message>
        <source>Max correction</source>
        <translation>Макс. коррекция</translation>
    </message>
    <message>
        <source>Max step per part</source>
        <translation>Макс. шаг за деталь</translation>
    </message>
    <message>
        <source>Dead band (EWMA)</source>
        <translation>Зона нечувств. (EWMA)</translation>
    </message>
    <message>
        <source>Filter (z + b)/(z − a)</source>
        <translation>Фильтр (z + b)/(z − a)</translation>
    </message>
    <message>
        <source>Point</source>
        <translation>Точка</translation>
    </message>
    <message>
        <source>R1 (error)</source>
        <translation>R1 (ошибка)</translation>
    </message>
    <message>
        <source>R2 (correction)</source>
        <translation>R2 (коррекция)</translation>
    </message>
    <message>
        <source>k_eff LQG</source>
        <translation>k_eff LQG</translation>
    </message>
    <message>
        <source>k_eff EWMA</source>
        <translation>k_eff EWMA</translation>
    </message>
    <message>
        <source>Gain marg.</source>
        <translation>Запас усил.</translation>
    </message>
    <message>
        <source>Delay, parts</source>
        <translation>Запас задержки</translation>
    </message>
    <message>
        <source>Disk α</source>
        <translation>Диск α</translation>
    </message>
    <message>
        <source>%1: %2 mm</source>
        <translation>%1: %2 мм</translation>
    </message>
    <message>
        <source>Apply…</source>
        <translation>Применить…</translation>
    </message>
    <message>
        <source>Revert</source>
        <translation>Вернуть</translation>
    </message>
    <message>
        <source>Step at point 1</source>
        <translation>Скачок в точке 1</translation>
    </message>
    <message>
        <source>part after the step</source>
        <translation>деталь после скачка</translation>
    </message>
    <message>
        <source>error / step</source>
        <translation>ошибка / скачок</translation>
    </message>
    <message>
        <source>|S| at point 1</source>
        <translation>|S| в точке 1</translation>
    </message>
    <message>
        <source>frequency, rad per part</source>
        <translation>частота, рад/дет.</translation>
    </message>
    <message>
        <source>|S|</source>
        <translation>|S|</translation>
    </message>
    <message>
        <source>The design is refused: %1</source>
        <translation>Синтез отклонён: %1</translation>
    </message>
    <message>
        <source>Re-synthesis %1 ms</source>
        <translation>Пересчёт %1 мс</translation>
    </message>
    <message>
        <source>Warning: a plant one part slower than the model destabilises this design (delay margin under one part). Best EWMA weight %1.</source>
        <translation>Внимание: объект с задержкой на одну деталь больше модели делает этот регулятор неустойчивым (запас по задержке меньше одной детали). Лучший вес EWMA %1.</translation>
    </message>
    <message>
        <source>The design tolerates one more part of delay. Best EWMA weight %1.</source>
        <translation>Регулятор выдерживает задержку на одну деталь больше. Лучший вес EWMA %1.</translation>
    </message>
    <message>
        <source>open</source>
        <translation>без рег.</translation>
    </message>
    <message>
        <source>EWMA</source>
        <translation>EWMA</translation>
    </message>
    <message>
        <source>LQG</source>
        <translation>LQG</translation>
    </message>
    <message>
        <source>Apply the new controller tuning from the next part?</source>
        <translation>Применить новую настройку регулятора со следующей детали?</translation>
    </message>
    <message>
        <source>Warning: its delay margin is under one part: a plant one part slower than the model destabilises it.</source>
        <translation>Внимание: запас по задержке меньше одной детали: объект с задержкой на одну деталь больше модели сделает контур неустойчивым.</translation>
    </message>
    <message>
        <source>Apply tuning</source>
        <translation>Применить настройку</translation>
    </message>
    <message>
        <source> mm</source>
        <translation> мм</translation>
    </message>
    <message>
        <source> mm²</source>
        <translation> мм²</translation>
    </message>
    <message>
        <source>Delay margin in parts (phase margin / crossover) / whole extra parts of delay the loop stays stable with</source>
        <translation>Запас по задержке в деталях (запас по фазе / частота среза) / сколько лишних деталей задержки контур выдерживает</translation>
    </message>
    <message>
        <source>Applied to the running loop: the new tuning takes over at the next part, without a jump in the correction.</source>
        <translation>Применено к работающему контуру: новая настройка действует со следующей детали, без скачка коррекции.</translation>
    </message>
    <message>
        <source>Applied: no run is going; the next Start on the Run page uses this tuning.</source>
        <translation>Применено: серия не идёт; следующий пуск на странице «Работа» использует эту настройку.</translation>
    </message>
    <message>
        <source>Integral action</source>
        <translation>Интегральное действие</translation>
    </message>
    <message>
        <source>Adds an integrating disturbance state to the LQG design: a step (tool change, new blanks) is corrected completely, at some cost in k_eff</source>
        <translation>Добавляет в расчёт LQG интегрирующее состояние возмущения: скачок (смена инструмента, новые заготовки) устраняется полностью ценой некоторой потери k_eff</translation>
    </message>
    <message>
        <source>weight</source>
        <translation>вес</translation>
    </message>
    <message>
        <source>Identify from history</source>
        <translation>Оценить по истории</translation>
    </message>
    <message>
        <source>Newest run</source>
        <translation>Последний прогон</translation>
    </message>
    <message>
        <source>Run %1</source>
        <translation>Прогон %1</translation>
    </message>
    <message numerus="yes">
        <source>%n parts, started %1</source>
        <translation>
            <numerusform>%n деталь, начат %1</numerusform>
            <numerusform>%n детали, начат %1</numerusform>
            <numerusform>%n деталей, начат %1</numerusform>
        </translation>
    </message>
    <message>
        <source>Identification failed: %1</source>
        <translation>Оценка не удалась: %1</translation>
    </message>
    <message>
        <source>Phase margin %1, sensitivity peak |S| %2.</source>
        <translation>Запас по фазе %1, пик чувствительности |S| %2.</translation>
    </message>
    <message>
        <source>Identifies the plant of a stored run at every point (gain, plant delay, disturbance as ARMA(p, q) with standard errors) and designs the controller for it</source>
        <translation>Идентифицирует объект сохранённой серии в каждой точке (коэффициент, задержка объекта, возмущение как ARMA(p, q) со стандартными ошибками) и рассчитывает для него регулятор</translation>
    </message>
    <message>
        <source>Identified model</source>
        <translation>Идентифицированная модель</translation>
    </message>
    <message>
        <source>Design on the identified model (per point gain and disturbance, the plant delay) instead of the typed filter</source>
        <translation>Расчёт по идентифицированной модели (коэффициент и возмущение по точкам, задержка объекта) вместо введённого фильтра</translation>
    </message>
    <message>
        <source>Use the loop&apos;s proposal (part %1)</source>
        <translation>Взять предложение контура (деталь %1)</translation>
    </message>
    <message>
        <source>The adaptive loop identified the plant and proposes a design for it; take it into the page, check the predictions and apply it</source>
        <translation>Адаптивный контур идентифицировал объект и предлагает для него расчёт; возьмите его на страницу, проверьте прогноз и примените</translation>
    </message>
    <message>
        <source>Identifying the plant of the stored run…</source>
        <translation>Идентификация объекта сохранённой серии…</translation>
    </message>
    <message>
        <source>Point %1: gain %2 ± %3, ARMA(%4, %5) AR [%6] MA [%7], σ² %8 mm², Ljung–Box p %9</source>
        <translation>Точка %1: коэффициент %2 ± %3, ARMA(%4, %5) AR [%6] MA [%7], σ² %8 мм², Льюнг–Бокс p %9</translation>
    </message>
    <message>
        <source>the design&apos;s margins hold (gain margin %1)</source>
        <translation>запасы расчёта выдержаны (запас по усилению %1)</translation>
    </message>
    <message>
        <source>the design fails its margins: %1</source>
        <translation>расчёт не выдерживает запасов: %1</translation>
    </message>
    <message>
        <source>Run %1, parts %2 .. %3: plant delay %4 parts; point 1 gain %5 ± %6 (every point in the tooltip); %7</source>
        <translation>Серия %1, детали %2 .. %3: задержка объекта %4 дет.; точка 1: коэффициент %5 ± %6 (все точки в подсказке); %7</translation>
    </message>
    <message>
        <source>Point %1: gain %2 ± %3, σ² %4 mm²</source>
        <translation>Точка %1: коэффициент %2 ± %3, σ² %4 мм²</translation>
    </message>
    <message>
        <source>The loop&apos;s proposal of part %1: plant delay %2 parts, identified from %3</source>
        <translation>Предложение контура на детали %1: задержка объекта %2 дет., идентифицировано по %3</translation>
    </message>
    <message>
        <source>The proposal cannot be used: %1</source>
        <translation>Предложение нельзя использовать: %1</translation>
    </message>
</context>
<context>
    <name>tt::ui::CornerMoveEditor</name>
    <message>
        <source>Corner between two moves</source>
        <translation>Угол между двумя перемещениями</translation>
    </message>
    <message>
        <source>Corner</source>
        <translation>Угол</translation>
    </message>
    <message>
        <source>X before</source>
        <translation>X до</translation>
    </message>
    <message>
        <source>Z before</source>
        <translation>Z до</translation>
    </message>
    <message>
        <source>X after</source>
        <translation>X после</translation>
    </message>
    <message>
        <source>Z after</source>
        <translation>Z после</translation>
    </message>
    <message>
        <source> rad/s</source>
        <translation> рад/с</translation>
    </message>
    <message>
        <source>Pulse on</source>
        <translation>Импульс на</translation>
    </message>
    <message>
        <source>X, cross slide</source>
        <translation>X, поперечный</translation>
    </message>
    <message>
        <source>Z, carriage</source>
        <translation>Z, продольный</translation>
    </message>
    <message>
        <source>Pulse length</source>
        <translation>Длительность</translation>
    </message>
    <message>
        <source> ms</source>
        <translation> мс</translation>
    </message>
    <message>
        <source>Speeds as entered</source>
        <translation>Вручную</translation>
    </message>
    <message>
        <source>%1: X %2 → %3, Z %4 → %5</source>
        <translation>%1: X %2 → %3, Z %4 → %5</translation>
    </message>
</context>
<context>
    <name>tt::ui::CornerTool</name>
    <message>
        <source>Corner pulse</source>
        <translation>Импульс на углах</translation>
    </message>
    <message>
        <source>Simulate</source>
        <translation>Смоделировать</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Отмена</translation>
    </message>
    <message>
        <source>Paths</source>
        <translation>Траектории</translation>
    </message>
    <message>
        <source>Network</source>
        <translation>Сеть</translation>
    </message>
    <message>
        <source>Drift monitor</source>
        <translation>Контроль дрейфа</translation>
    </message>
    <message>
        <source>Zoom on the corner</source>
        <translation>Крупно у угла</translation>
    </message>
    <message>
        <source>Training moves</source>
        <translation>Обучающие перемещения</translation>
    </message>
    <message>
        <source>Train network</source>
        <translation>Обучить сеть</translation>
    </message>
    <message>
        <source>Corners</source>
        <translation>Углов</translation>
    </message>
    <message>
        <source>Run corners</source>
        <translation>Пройти углы</translation>
    </message>
    <message>
        <source>Retrain now</source>
        <translation>Переобучить</translation>
    </message>
    <message>
        <source>Nothing running.</source>
        <translation>Расчёт не идёт.</translation>
    </message>
    <message>
        <source>The corner preset cannot be read: %1</source>
        <translation>Не удаётся прочитать набор параметров угла: %1</translation>
    </message>
    <message>
        <source>Error %1 → %2 µm, −%3 %</source>
        <translation>Ошибка %1 → %2 мкм, −%3 %</translation>
    </message>
    <message>
        <source>Network&apos;s pulse %1 V</source>
        <translation>Импульс сети %1 В</translation>
    </message>
    <message>
        <source>Best pulse %1 V; no network for this pulse yet</source>
        <translation>Лучший импульс %1 В; сети для такого импульса ещё нет</translation>
    </message>
    <message>
        <source>Network trained.</source>
        <translation>Сеть обучена.</translation>
    </message>
    <message>
        <source>Run finished.</source>
        <translation>Прогон закончен.</translation>
    </message>
    <message>
        <source>Finding the best pulse of training move %1 of %2</source>
        <translation>Поиск лучшего импульса: перемещение %1 из %2</translation>
    </message>
    <message>
        <source>Training the network: epoch %1 of at most %2</source>
        <translation>Обучение сети: эпоха %1 из не более чем %2</translation>
    </message>
    <message>
        <source>Running corner %1 of %2</source>
        <translation>Угол %1 из %2</translation>
    </message>
    <message>
        <source>Retraining the network: epoch %1 of at most %2</source>
        <translation>Переобучение сети: эпоха %1 из не более чем %2</translation>
    </message>
    <message>
        <source>Cancelled: the network of before is kept.</source>
        <translation>Отменено: прежняя сеть сохранена.</translation>
    </message>
    <message>
        <source>Failed: %1</source>
        <translation>Ошибка: %1</translation>
    </message>
    <message>
        <source>No network yet. Training finds the best pulse of each training move on the simulator (a bracketed search of U = k1·e_max + k2·e_mean), then the 4-10-1 network learns it from the four motor speeds.</source>
        <translation>Сети ещё нет. Обучение находит на симуляторе лучший импульс каждого обучающего перемещения (одномерный поиск минимума U = k1·e_max + k2·e_mean на отрезке), затем сеть 4-10-1 учится выдавать его по четырём скоростям двигателей.</translation>
    </message>
    <message>
        <source>Network 4-%1-1 for a %2 ms pulse on %3: %4 epochs (best %5), RMS amplitude error %6 mV on the training moves, %7 mV on the validation moves. The best pulses cut the training moves&apos; error by %8 %.</source>
        <translation>Сеть 4-%1-1 для импульса %2 мс на %3: %4 эпох (лучшая %5), СКО амплитуды %6 мВ на обучающих перемещениях, %7 мВ на проверочных. Лучшие импульсы снижают ошибку обучающих перемещений на %8 %.</translation>
    </message>
    <message numerus="yes">
        <source>Retrained %n time(s) since.</source>
        <translation>
            <numerusform>С тех пор переобучена %n раз.</numerusform>
            <numerusform>С тех пор переобучена %n раза.</numerusform>
            <numerusform>С тех пор переобучена %n раз.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n corner(s): mean error %1 → %2 µm (−%3 %).</source>
        <translation>
            <numerusform>%n угол: средняя ошибка %1 → %2 мкм (−%3 %).</numerusform>
            <numerusform>%n угла: средняя ошибка %1 → %2 мкм (−%3 %).</numerusform>
            <numerusform>%n углов: средняя ошибка %1 → %2 мкм (−%3 %).</numerusform>
        </translation>
    </message>
    <message>
        <source>No retraining was needed.</source>
        <translation>Переобучение не понадобилось.</translation>
    </message>
    <message>
        <source>After it: −%1 %.</source>
        <translation>После этого: −%1 %.</translation>
    </message>
    <message>
        <source>Drift</source>
        <translation>Дрейф</translation>
    </message>
    <message>
        <source>Friction</source>
        <translation>Трение</translation>
    </message>
    <message>
        <source>Velocity gain</source>
        <translation>Усиление по скорости</translation>
    </message>
    <message>
        <source>Inertia</source>
        <translation>Инерция</translation>
    </message>
    <message numerus="yes">
        <source>Retrained on demand on %n corner(s); identified %1.</source>
        <translation>
            <numerusform>Переобучена по запросу на %n угле; определено: %1.</numerusform>
            <numerusform>Переобучена по запросу на %n углах; определено: %1.</numerusform>
            <numerusform>Переобучена по запросу на %n углах; определено: %1.</numerusform>
        </translation>
    </message>
    <message>
        <source>Retraining on demand refused: %1. The network in use is kept.</source>
        <translation>Переобучение по запросу отклонено: %1. Сохранена прежняя сеть.</translation>
    </message>
    <message>
        <source>Identifying the drives from the recorded corners</source>
        <translation>Идентификация приводов по записанным углам</translation>
    </message>
    <message>
        <source>Finding the best pulse of move %1 of %2 on the identified drives</source>
        <translation>Поиск лучшего импульса на идентифицированных приводах: перемещение %1 из %2</translation>
    </message>
    <message>
        <source>X: friction × %1, inertia × %2, gain × %3; Z: friction × %4, inertia × %5, gain × %6</source>
        <translation>X: трение × %1, инерция × %2, усиление × %3; Z: трение × %4, инерция × %5, усиление × %6</translation>
    </message>
    <message>
        <source>Measured cost %1 % off the prediction after corner %2; identified %3.</source>
        <translation>После угла %2 измеренная цель отличается от расчётной на %1 %; определено: %3.</translation>
    </message>
    <message>
        <source>Retrained: validation cost %1 → %2 µm.</source>
        <translation>Переобучена: цель на проверочных перемещениях %1 → %2 мкм.</translation>
    </message>
    <message>
        <source>The retrained network was refused (%1); the network in use is kept.</source>
        <translation>Переобученная сеть отклонена (%1); сохранена прежняя сеть.</translation>
    </message>
    <message>
        <source>Runs corners with the network&apos;s pulse on the simulated machine; from the middle corner on, the chosen property of the chosen drive is multiplied by the factor. After each corner the monitor compares the measured cost with the predicted one over the last %1 corners (misses removed) and retrains above %2 %; a retrained network is taken only when it does better on held-out moves.</source>
        <translation>Проходит углы с импульсом сети на моделируемом станке; с середины прогона выбранный параметр выбранного привода умножается на заданный множитель. После каждого угла контроль сравнивает измеренное значение цели с расчётным по последним %1 углам (промахи исключены) и переобучает сеть, если разница больше %2 %; переобученная сеть принимается, только если она лучше на проверочных перемещениях.</translation>
    </message>
    <message numerus="yes">
        <source>%n more retraining(s) later.</source>
        <translation>
            <numerusform>Позже ещё %n переобучение.</numerusform>
            <numerusform>Позже ещё %n переобучения.</numerusform>
            <numerusform>Позже ещё %n переобучений.</numerusform>
        </translation>
    </message>
    <message>
        <source>Last difference of the monitor: %1 % (threshold %2 %).</source>
        <translation>Последняя разница контроля: %1 % (порог %2 %).</translation>
    </message>
    <message>
        <source>On the drives as identified after the drift.</source>
        <translation>На приводах, идентифицированных после дрейфа.</translation>
    </message>
    <message>
        <source>Drive</source>
        <translation>Привод</translation>
    </message>
    <message>
        <source>Machine</source>
        <translation>Станок</translation>
    </message>
    <message>
        <source>Paper&apos;s drives</source>
        <translation>Приводы статьи</translation>
    </message>
    <message>
        <source>Soft drives</source>
        <translation>Мягкие приводы</translation>
    </message>
    <message>
        <source>Paper&apos;s drives: the 1V340F30 lathe of paper 002 (Kv 16.7 1/s), where drifts of the inertia hardly move the best pulse. Soft drives: the same lathe with half the position loop gain (Kv 8.35 1/s) and a slow cross slide (50 ms), where they do.</source>
        <translation>Приводы статьи: токарный станок 1В340Ф30 из статьи 002 (Kv 16,7 1/с), на котором дрейф момента инерции почти не меняет лучший импульс. Мягкие приводы: тот же станок с вдвое меньшим коэффициентом контура положения (Kv 8,35 1/с) и медленным поперечным суппортом (50 мс), на котором меняет.</translation>
    </message>
</context>
<context>
    <name>tt::ui::DeformationModelPanel</name>
    <message>
        <source>Terms of the next fit</source>
        <translation>Члены следующей модели</translation>
    </message>
    <message>
        <source>cubic in z (a, f quadratic)</source>
        <translation>кубическая по z (по a, f квадратичная)</translation>
    </message>
    <message>
        <source>full quadratic</source>
        <translation>полная квадратичная</translation>
    </message>
    <message>
        <source>linear with interactions</source>
        <translation>линейная с взаимодействиями</translation>
    </message>
    <message>
        <source>linear</source>
        <translation>линейная</translation>
    </message>
    <message>
        <source>Remove insignificant terms</source>
        <translation>Исключать незначимые члены</translation>
    </message>
    <message>
        <source>Term (coded)</source>
        <translation>Член (кодир.)</translation>
    </message>
    <message>
        <source>Coefficient, µm</source>
        <translation>Коэффициент, мкм</translation>
    </message>
    <message>
        <source>Std. error, µm</source>
        <translation>Ст. ошибка, мкм</translation>
    </message>
    <message>
        <source>t-value</source>
        <translation>Критерий t</translation>
    </message>
    <message>
        <source>No model yet.</source>
        <translation>Модели пока нет.</translation>
    </message>
    <message>
        <source>significant at 95 %</source>
        <translation>значима при 95 %</translation>
    </message>
    <message>
        <source>NOT significant at 95 %</source>
        <translation>НЕ значима при 95 %</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1 points, %2 terms.&lt;/b&gt; R² %3, adjusted R² %4. F %5 against the table value F(0.95; %6, %7) = %8: %9. Residual 2σ %10 µm. t-values below %11 are not significant.</source>
        <translation>&lt;b&gt;Точек: %1, членов: %2.&lt;/b&gt; R² %3, скорректированный R² %4. F %5 при табличном F(0,95; %6, %7) = %8: %9. Остаточное 2σ %10 мкм. Члены с t ниже %11 незначимы.</translation>
    </message>
    <message>
        <source>Removed as insignificant: %1</source>
        <translation>Исключены как незначимые: %1</translation>
    </message>
</context>
<context>
    <name>tt::ui::DevicesPage</name>
    <message>
        <source>%1 — %2</source>
        <translation>%1 — %2</translation>
    </message>
    <message>
        <source>New: %1
(not added yet)</source>
        <translation>Новое: %1
(ещё не добавлено)</translation>
    </message>
    <message>
        <source>ready</source>
        <translation>готово</translation>
    </message>
    <message>
        <source>connecting</source>
        <translation>подключение</translation>
    </message>
    <message>
        <source>error</source>
        <translation>ошибка</translation>
    </message>
    <message>
        <source>closed</source>
        <translation>закрыто</translation>
    </message>
    <message>
        <source>Settings to correct: %1 (marked in red).</source>
        <translation>Исправьте настройки: %1 (выделены красным).</translation>
    </message>
    <message>
        <source>Remove device</source>
        <translation>Удалить устройство</translation>
    </message>
    <message>
        <source>Remove %1? Its settings are deleted; the loop can no longer use it.</source>
        <translation>Удалить устройство «%1»? Его настройки будут удалены, и контур управления больше не сможет его использовать.</translation>
    </message>
    <message>
        <source>Not tested: correct the settings marked in red first.</source>
        <translation>Не проверено: сначала исправьте настройки, выделенные красным.</translation>
    </message>
    <message>
        <source>Testing the connection…</source>
        <translation>Проверка связи…</translation>
    </message>
    <message>
        <source>No connection: %1</source>
        <translation>Нет связи: %1</translation>
    </message>
    <message>
        <source>Connected: %1</source>
        <translation>Связь есть: %1</translation>
    </message>
    <message>
        <source>Connected — %1</source>
        <translation>Связь есть — %1</translation>
    </message>
    <message>
        <source>No answer within %1 s: %2</source>
        <translation>Нет ответа в течение %1 с: %2</translation>
    </message>
    <message>
        <source>Not added</source>
        <translation>Не добавлено</translation>
    </message>
    <message>
        <source>Fill in the settings, test the connection, then add the device.</source>
        <translation>Заполните настройки, проверьте связь, затем добавьте устройство.</translation>
    </message>
    <message>
        <source>none</source>
        <translation>нет</translation>
    </message>
    <message>
        <source>Ready</source>
        <translation>Готово</translation>
    </message>
    <message>
        <source>Connecting</source>
        <translation>Подключение</translation>
    </message>
    <message>
        <source>Error</source>
        <translation>Ошибка</translation>
    </message>
    <message>
        <source>Closed</source>
        <translation>Закрыто</translation>
    </message>
    <message>
        <source>%1 (last value)</source>
        <translation>%1 (последнее значение)</translation>
    </message>
    <message>
        <source>Device instances</source>
        <translation>Список устройств</translation>
    </message>
    <message>
        <source>Add a device of type</source>
        <translation>Добавить устройство типа</translation>
    </message>
    <message>
        <source>Add</source>
        <translation>Добавить</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Удалить</translation>
    </message>
    <message>
        <source>No device selected</source>
        <translation>Устройство не выбрано</translation>
    </message>
    <message>
        <source>Add a gauge micrometer, probe mandrel, drive-current readout or correction output to the CNC. The built-in simulator provides every kind, with fault switches.</source>
        <translation>Добавьте цифровой микрометр, оправку-датчик, датчик тока привода или выход коррекции в ЧПУ. Встроенный симулятор предоставляет устройства всех типов с переключателями неисправностей.</translation>
    </message>
    <message>
        <source>State</source>
        <translation>Состояние</translation>
    </message>
    <message>
        <source>Live value</source>
        <translation>Текущее значение</translation>
    </message>
    <message>
        <source>Last error</source>
        <translation>Последняя ошибка</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Название</translation>
    </message>
    <message>
        <source>Settings</source>
        <translation>Настройки</translation>
    </message>
    <message>
        <source>Test connection</source>
        <translation>Проверить связь</translation>
    </message>
    <message>
        <source>Add device</source>
        <translation>Добавить устройство</translation>
    </message>
    <message>
        <source>Apply</source>
        <translation>Применить</translation>
    </message>
    <message>
        <source>Revert</source>
        <translation>Вернуть</translation>
    </message>
    <message>
        <source>Simulator fault switches</source>
        <translation>Неисправности симулятора</translation>
    </message>
    <message>
        <source>Silent</source>
        <translation>Молчит</translation>
    </message>
    <message>
        <source>Noisy</source>
        <translation>Шумит</translation>
    </message>
    <message>
        <source>Stuck value</source>
        <translation>Залипшее значение</translation>
    </message>
    <message>
        <source>Malformed frames</source>
        <translation>Искажённые кадры</translation>
    </message>
    <message>
        <source>Unplugged</source>
        <translation>Кабель отключён</translation>
    </message>
    <message>
        <source>Counters</source>
        <translation>Счётчики</translation>
    </message>
    <message>
        <source>Not tested: a run is going on the Run page and would take the test reading as a diameter. Stop the run first.</source>
        <translation>Не проверено: на странице «Работа» идёт серия, и контрольное показание было бы принято за диаметр. Сначала остановите серию.</translation>
    </message>
    <message>
        <source>Not tested: a run is going on the Run page and these settings would close the device it uses. Stop the run first, or test with the applied settings.</source>
        <translation>Не проверено: на странице «Работа» идёт серия, а эти настройки закрыли бы используемое ею устройство. Сначала остановите серию или проверьте с применёнными настройками.</translation>
    </message>
    <message>
        <source>changed settings of a device on the Devices page</source>
        <translation>изменённые настройки устройства на странице «Устройства»</translation>
    </message>
</context>
<context>
    <name>tt::ui::FeedChartTabs</name>
    <message>
        <source>Feed</source>
        <translation>Подача</translation>
    </message>
    <message>
        <source>Spool and magnet</source>
        <translation>Золотник, магнит</translation>
    </message>
    <message>
        <source>Sweep</source>
        <translation>Перебор</translation>
    </message>
    <message>
        <source>Sweep table</source>
        <translation>Таблица</translation>
    </message>
    <message>
        <source>time, s</source>
        <translation>время, с</translation>
    </message>
    <message>
        <source>feed, mm/s</source>
        <translation>подача, мм/с</translation>
    </message>
    <message>
        <source>slot opening, mm</source>
        <translation>открытие щели, мм</translation>
    </message>
    <message>
        <source>magnet current, mA</source>
        <translation>ток магнита, мА</translation>
    </message>
    <message>
        <source>Feed after the load step, with and without the regulator</source>
        <translation>Подача после скачка нагрузки, с регулятором и без</translation>
    </message>
    <message>
        <source>Slot opening</source>
        <translation>Открытие щели</translation>
    </message>
    <message>
        <source>Magnet current</source>
        <translation>Ток магнита</translation>
    </message>
    <message>
        <source>set feed</source>
        <translation>заданная подача</translation>
    </message>
    <message>
        <source>without regulator</source>
        <translation>без регулятора</translation>
    </message>
    <message>
        <source>with regulator</source>
        <translation>с регулятором</translation>
    </message>
    <message>
        <source>Feed after the load step for each ξ</source>
        <translation>Подача после скачка нагрузки при каждом ξ</translation>
    </message>
    <message>
        <source>Feed after the load step for each gain</source>
        <translation>Подача после скачка нагрузки при каждом усилении</translation>
    </message>
    <message>
        <source>ξ</source>
        <translation>ξ</translation>
    </message>
    <message>
        <source>gain K_a</source>
        <translation>K_a</translation>
    </message>
    <message>
        <source>feed,
mm/s</source>
        <translation>подача,
мм/с</translation>
    </message>
    <message>
        <source>settling,
s</source>
        <translation>t уст.,
с</translation>
    </message>
    <message>
        <source>overshoot,
%</source>
        <translation>перерег.,
%</translation>
    </message>
    <message>
        <source>spool
overshoot, %</source>
        <translation>перерег.
золотника, %</translation>
    </message>
    <message>
        <source>regulates</source>
        <translation>регулирует</translation>
    </message>
    <message>
        <source>no: runs away</source>
        <translation>нет: уходит</translation>
    </message>
    <message>
        <source>slot fully open</source>
        <translation>на упоре</translation>
    </message>
    <message>
        <source>yes</source>
        <translation>да</translation>
    </message>
    <message>
        <source>gain ×
K_p</source>
        <translation>усиление ×
K_p</translation>
    </message>
    <message>
        <source>no: unstable</source>
        <translation>нет: неустойчив</translation>
    </message>
</context>
<context>
    <name>tt::ui::FeedParameterForm</name>
    <message>
        <source>Sensor: the tool&apos;s elastic displacement</source>
        <translation>Датчик упругого перемещения резца</translation>
    </message>
    <message>
        <source>Amplifier</source>
        <translation>Усилитель</translation>
    </message>
    <message>
        <source>Electromagnet and armature</source>
        <translation>Электромагнит и якорь</translation>
    </message>
    <message>
        <source>Spool of the flow regulator</source>
        <translation>Золотник регулятора расхода</translation>
    </message>
    <message>
        <source>Slot of the flow regulator</source>
        <translation>Щель регулятора расхода</translation>
    </message>
    <message>
        <source>Cylinder and carriage</source>
        <translation>Силовой цилиндр и суппорт</translation>
    </message>
    <message>
        <source>Signal per newton</source>
        <translation>Сигнал на ньютон</translation>
    </message>
    <message>
        <source>mV/N</source>
        <translation>мВ/Н</translation>
    </message>
    <message>
        <source>Feed exponent y</source>
        <translation>Показатель подачи y</translation>
    </message>
    <message>
        <source>Gain K_a</source>
        <translation>Усиление K_a</translation>
    </message>
    <message>
        <source>V/V</source>
        <translation>В/В</translation>
    </message>
    <message>
        <source>Bias U₀</source>
        <translation>Смещение U₀</translation>
    </message>
    <message>
        <source>V</source>
        <translation>В</translation>
    </message>
    <message>
        <source>Coil turns</source>
        <translation>Витков катушки</translation>
    </message>
    <message>
        <source>Gap permeance</source>
        <translation>Проводимость зазора</translation>
    </message>
    <message>
        <source>µH</source>
        <translation>мкГн</translation>
    </message>
    <message>
        <source>Gap section</source>
        <translation>Сечение зазора</translation>
    </message>
    <message>
        <source>mm²</source>
        <translation>мм²</translation>
    </message>
    <message>
        <source>Coil circuit r</source>
        <translation>Цепь катушки r</translation>
    </message>
    <message>
        <source>Ω</source>
        <translation>Ом</translation>
    </message>
    <message>
        <source>Time constant T_z</source>
        <translation>Постоянная T_z</translation>
    </message>
    <message>
        <source>ms</source>
        <translation>мс</translation>
    </message>
    <message>
        <source>Damping ratio ξ</source>
        <translation>Демпфирование ξ</translation>
    </message>
    <message>
        <source>Gain K_z</source>
        <translation>Усиление K_z</translation>
    </message>
    <message>
        <source>µm/N</source>
        <translation>мкм/Н</translation>
    </message>
    <message>
        <source>Lap</source>
        <translation>Перекрытие</translation>
    </message>
    <message>
        <source>mm</source>
        <translation>мм</translation>
    </message>
    <message>
        <source>Discharge coeff. μ</source>
        <translation>Коэф. расхода μ</translation>
    </message>
    <message>
        <source>Plunger d₁</source>
        <translation>Плунжер d₁</translation>
    </message>
    <message>
        <source>Pressure drop</source>
        <translation>Перепад давления</translation>
    </message>
    <message>
        <source>MPa</source>
        <translation>МПа</translation>
    </message>
    <message>
        <source>Oil density</source>
        <translation>Плотность масла</translation>
    </message>
    <message>
        <source>kg/m³</source>
        <translation>кг/м³</translation>
    </message>
    <message>
        <source>Full opening</source>
        <translation>Полное открытие</translation>
    </message>
    <message>
        <source>Carriage mass</source>
        <translation>Масса суппорта</translation>
    </message>
    <message>
        <source>kg</source>
        <translation>кг</translation>
    </message>
    <message>
        <source>Piston D</source>
        <translation>Поршень D</translation>
    </message>
    <message>
        <source>Leakage k_y</source>
        <translation>Утечки k_y</translation>
    </message>
    <message>
        <source>mm³/(s·Pa)</source>
        <translation>мм³/(с·Па)</translation>
    </message>
    <message>
        <source>Set feed S</source>
        <translation>Заданная подача S</translation>
    </message>
    <message>
        <source>mm/s</source>
        <translation>мм/с</translation>
    </message>
    <message>
        <source>%1 .. %2 %3</source>
        <translation>%1 .. %2 %3</translation>
    </message>
    <message>
        <source>Design gain for the load</source>
        <translation>Рассчитать усиление</translation>
    </message>
    <message>
        <source>The radial force follows the chip: P_y = P (v/S)^y; y = 0 is the paper&apos;s constant force.</source>
        <translation>Радиальная сила следует за толщиной среза: P_y = P (v/S)^y; y = 0 — постоянная сила, как в статье.</translation>
    </message>
    <message>
        <source>Bias current %1 mA; the lap that keeps the slot shut at the bias: %2 mm.</source>
        <translation>Ток смещения %1 мА; перекрытие, при котором щель закрыта при смещении: %2 мм.</translation>
    </message>
    <message>
        <source>L = %1 H, T_k = %2 ms, K_e = %3 N/A²</source>
        <translation>L = %1 Гн, T_k = %2 мс, K_e = %3 Н/А²</translation>
    </message>
    <message>
        <source>ξ &lt; 1: the spool oscillates (the paper recommends ξ slightly above 1).</source>
        <translation>ξ &lt; 1: золотник колеблется (в статье рекомендовано ξ немного больше 1).</translation>
    </message>
    <message>
        <source>ξ ≥ 1: aperiodic, settles in about 3T.</source>
        <translation>ξ ≥ 1: апериодический процесс, длится около 3T.</translation>
    </message>
    <message>
        <source>k_s = %1 m²/s; full flow %2 cm³/s</source>
        <translation>k_s = %1 м²/с; полный расход %2 см³/с</translation>
    </message>
    <message>
        <source>F = %1 cm², k₀ = %2 m⁻², T_c = %3 ms, pump %4 cm³/s</source>
        <translation>F = %1 см², k₀ = %2 м⁻², T_c = %3 мс, насос %4 см³/с</translation>
    </message>
</context>
<context>
    <name>tt::ui::FeedScheduleTool</name>
    <message>
        <source>Feed schedule</source>
        <translation>Программа подачи</translation>
    </message>
    <message>
        <source>The built-in set-up cannot be read: %1</source>
        <translation>Встроенную наладку не удаётся прочитать: %1</translation>
    </message>
    <message>
        <source>Experiments on the simulator</source>
        <translation>Эксперименты на симуляторе</translation>
    </message>
    <message>
        <source>Experiment to fit</source>
        <translation>Эксперимент для модели</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>Файлы CSV (*.csv)</translation>
    </message>
    <message>
        <source>Fitting</source>
        <translation>Построение модели</translation>
    </message>
    <message>
        <source>Model file</source>
        <translation>Файл модели</translation>
    </message>
    <message>
        <source>Model files (*.json)</source>
        <translation>Файлы моделей (*.json)</translation>
    </message>
    <message>
        <source>%1 cannot be used: %2</source>
        <translation>%1 нельзя использовать: %2</translation>
    </message>
    <message>
        <source>Machining on the simulator</source>
        <translation>Обработка на симуляторе</translation>
    </message>
    <message>
        <source>Stopped.</source>
        <translation>Остановлено.</translation>
    </message>
    <message>
        <source>Deformation Y; the tool travels z %1 → %2 mm</source>
        <translation>Деформация Y; резец идёт по z %1 → %2 мм</translation>
    </message>
    <message>
        <source>%1 mm/rev</source>
        <translation>%1 мм/об</translation>
    </message>
    <message>
        <source>Yc</source>
        <translation>Yc</translation>
    </message>
    <message>
        <source>scheduled</source>
        <translation>по программе</translation>
    </message>
    <message>
        <source>scheduled feed</source>
        <translation>подача по программе</translation>
    </message>
    <message>
        <source>fmin</source>
        <translation>fmin</translation>
    </message>
    <message>
        <source>fmax</source>
        <translation>fmax</translation>
    </message>
    <message>
        <source>Save the CNC program</source>
        <translation>Сохранить программу ЧПУ</translation>
    </message>
    <message>
        <source>CNC programs (*.nc *.txt)</source>
        <translation>Программы ЧПУ (*.nc *.txt)</translation>
    </message>
    <message>
        <source>%1 cannot be written: %2</source>
        <translation>%1 не удаётся записать: %2</translation>
    </message>
    <message>
        <source>The program was written to %1.</source>
        <translation>Программа записана в %1.</translation>
    </message>
    <message>
        <source>No model yet.</source>
        <translation>Модели пока нет.</translation>
    </message>
    <message>
        <source>Simulated experiments (%1)</source>
        <translation>Эксперименты на симуляторе (%1)</translation>
    </message>
    <message>
        <source>%1: %2 points, %3 terms. R² %4, F %5 (table %6), 2σ %7 µm.</source>
        <translation>%1: точек %2, членов %3. R² %4, F %5 (табл. %6), 2σ %7 мкм.</translation>
    </message>
    <message>
        <source>%1 µm</source>
        <translation>%1 мкм</translation>
    </message>
    <message>
        <source>Y1 %1 µm
quality</source>
        <translation>Y1 %1 мкм
точность</translation>
    </message>
    <message>
        <source>Y2 %1 µm
output</source>
        <translation>Y2 %1 мкм
скорость</translation>
    </message>
    <message>
        <source>– µm</source>
        <translation>– мкм</translation>
    </message>
    <message>
        <source>Y1
quality</source>
        <translation>Y1
точность</translation>
    </message>
    <message>
        <source>Y2
output</source>
        <translation>Y2
скорость</translation>
    </message>
    <message numerus="yes">
        <source>&lt;b&gt;%n segment(s)&lt;/b&gt;, feeds %1 → %2 mm/rev.</source>
        <translation>
            <numerusform>&lt;b&gt;%n участок&lt;/b&gt;, подачи %1 → %2 мм/об.</numerusform>
            <numerusform>&lt;b&gt;%n участка&lt;/b&gt;, подачи %1 → %2 мм/об.</numerusform>
            <numerusform>&lt;b&gt;%n участков&lt;/b&gt;, подачи %1 → %2 мм/об.</numerusform>
        </translation>
    </message>
    <message>
        <source>Time %1 min against %2 min at fmin: &lt;b&gt;%3 % saved&lt;/b&gt; (fmax %4 min).</source>
        <translation>Время %1 мин против %2 мин при fmin: &lt;b&gt;экономия %3 %&lt;/b&gt; (fmax %4 мин).</translation>
    </message>
    <message>
        <source>The model names no machine job (spindle speed): no times, no program.</source>
        <translation>В модели нет наладки станка (частоты вращения): нет времени и программы.</translation>
    </message>
    <message>
        <source>Simulator: within &lt;b&gt;%1 %&lt;/b&gt; of Yc (worst at z %2 mm); constant fmax exceeds Yc by %3 %.</source>
        <translation>Симулятор: в пределах &lt;b&gt;%1 %&lt;/b&gt; от Yc (хуже всего при z %2 мм); постоянная fmax превышает Yc на %3 %.</translation>
    </message>
    <message>
        <source>No simulator for this model&apos;s set-up: the check is not available.</source>
        <translation>Для наладки этой модели нет симулятора: проверка недоступна.</translation>
    </message>
    <message>
        <source>Force-deformation model Y(a, f, z)</source>
        <translation>Модель силовой деформации Y(a, f, z)</translation>
    </message>
    <message>
        <source>Simulate</source>
        <translation>Симуляция</translation>
    </message>
    <message>
        <source>Run the experiments on the simulator and fit the model</source>
        <translation>Провести эксперименты на симуляторе и построить модель</translation>
    </message>
    <message>
        <source>Fit CSV…</source>
        <translation>Из CSV…</translation>
    </message>
    <message>
        <source>Load…</source>
        <translation>Файл…</translation>
    </message>
    <message>
        <source>Load a model file written by &apos;trueturn fit-deformation --json&apos;</source>
        <translation>Загрузить файл модели, записанный командой «trueturn fit-deformation --json»</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Отмена</translation>
    </message>
    <message>
        <source>Pass</source>
        <translation>Проход</translation>
    </message>
    <message>
        <source>Depth of cut a</source>
        <translation>Глубина резания a</translation>
    </message>
    <message>
        <source> mm</source>
        <translation> мм</translation>
    </message>
    <message>
        <source>Feeds, mm/rev</source>
        <translation>Подачи, мм/об</translation>
    </message>
    <message>
        <source>Pass z, mm</source>
        <translation>Проход по z, мм</translation>
    </message>
    <message>
        <source>Shortest segment</source>
        <translation>Мин. участок</translation>
    </message>
    <message>
        <source>CNC dialect</source>
        <translation>Диалект ЧПУ</translation>
    </message>
    <message>
        <source>Fanuc-style</source>
        <translation>в стиле Fanuc</translation>
    </message>
    <message>
        <source>LinuxCNC</source>
        <translation>LinuxCNC</translation>
    </message>
    <message>
        <source>Check on simulator</source>
        <translation>Проверить на симуляторе</translation>
    </message>
    <message>
        <source>Save program…</source>
        <translation>Сохранить программу…</translation>
    </message>
    <message>
        <source>Level Yc</source>
        <translation>Уровень Yc</translation>
    </message>
    <message>
        <source>z, mm</source>
        <translation>z, мм</translation>
    </message>
    <message>
        <source>Y, µm</source>
        <translation>Y, мкм</translation>
    </message>
    <message>
        <source>f, mm/rev</source>
        <translation>f, мм/об</translation>
    </message>
    <message>
        <source>Curves</source>
        <translation>Кривые</translation>
    </message>
    <message>
        <source>CNC program</source>
        <translation>Программа ЧПУ</translation>
    </message>
    <message>
        <source>Model statistics</source>
        <translation>Статистика модели</translation>
    </message>
    <message>
        <source>Refining the model</source>
        <translation>Уточнение модели</translation>
    </message>
    <message>
        <source>Refining: round %1, bar %2 of %3</source>
        <translation>Уточнение: раунд %1, образец %2 из %3</translation>
    </message>
    <message>
        <source>Refined at a = %1 mm (%2, test bars added: %3)</source>
        <translation>Уточнена при a = %1 мм (%2, добавлено образцов: %3)</translation>
    </message>
    <message numerus="yes">
        <source>Refined in %n round(s): test bars %1, gauge points %2; before, the pass was %3 % off Yc.</source>
        <translation>
            <numerusform>Уточнено за %n раунд: образцов %1, точек замера %2; до этого проход отклонялся от Yc на %3 %.</numerusform>
            <numerusform>Уточнено за %n раунда: образцов %1, точек замера %2; до этого проход отклонялся от Yc на %3 %.</numerusform>
            <numerusform>Уточнено за %n раундов: образцов %1, точек замера %2; до этого проход отклонялся от Yc на %3 %.</numerusform>
        </translation>
    </message>
    <message>
        <source>The feed step alone leaves the band: try the centred switch.</source>
        <translation>Один только шаг подачи выводит из допуска: попробуйте переключение по середине.</translation>
    </message>
    <message>
        <source>Simulator: &lt;b&gt;%1 %&lt;/b&gt; off Yc at z %2 mm, outside ±10 %.</source>
        <translation>Симулятор: отклонение от Yc &lt;b&gt;%1 %&lt;/b&gt; при z %2 мм, вне ±10 %.</translation>
    </message>
    <message>
        <source>Refine runs a targeted experiment at this depth, refits the model and checks again.</source>
        <translation>«Уточнить» проведёт целевой эксперимент на этой глубине, перестроит модель и проверит снова.</translation>
    </message>
    <message>
        <source>Refine</source>
        <translation>Уточнить</translation>
    </message>
    <message>
        <source>Machine targeted bars on the simulator, refit the model at this depth and check again</source>
        <translation>Обработать целевые образцы на симуляторе, перестроить модель на этой глубине и проверить снова</translation>
    </message>
    <message>
        <source>Where a feed step switches to the next: where the next feed reaches Yc (the paper), or where the two feeds&apos; mean is Yc (half the deviation)</source>
        <translation>Где подача сменяется следующей: где следующая подача достигает Yc (статья) или где среднее двух подач равно Yc (вдвое меньше отклонение)</translation>
    </message>
    <message>
        <source>at Yc (paper)</source>
        <translation>по статье</translation>
    </message>
    <message>
        <source>centred on Yc</source>
        <translation>вокруг Yc</translation>
    </message>
    <message>
        <source>Feed step, mm/rev</source>
        <translation>Шаг, мм/об</translation>
    </message>
</context>
<context>
    <name>tt::ui::FirstStartDialog</name>
    <message>
        <source>First start: create the administrator</source>
        <translation>Первый запуск: создание администратора</translation>
    </message>
    <message>
        <source>Create the administrator</source>
        <translation>Создайте администратора</translation>
    </message>
    <message>
        <source>No user exists yet. The administrator adds the operators, engineers and quality staff and sets what they may change. The password needs at least %1 characters.</source>
        <translation>Пользователей ещё нет. Администратор добавляет операторов, инженеров и сотрудников ОТК и определяет, что им разрешено менять. Пароль — не короче %1 символов.</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Имя</translation>
    </message>
    <message>
        <source>Password</source>
        <translation>Пароль</translation>
    </message>
    <message>
        <source>Repeat the password</source>
        <translation>Повторите пароль</translation>
    </message>
    <message>
        <source>Create and log in</source>
        <translation>Создать и войти</translation>
    </message>
    <message>
        <source>Quit</source>
        <translation>Выйти</translation>
    </message>
    <message>
        <source>The two passwords differ; type them again.</source>
        <translation>Пароли не совпадают; введите их ещё раз.</translation>
    </message>
    <message>
        <source>Not created: %1</source>
        <translation>Не создан: %1</translation>
    </message>
</context>
<context>
    <name>tt::ui::HistoryCheck</name>
    <message>
        <source>not available — %1</source>
        <translation>недоступна — %1</translation>
    </message>
    <message>
        <source>Run history</source>
        <translation>История серий</translation>
    </message>
    <message>
        <source>The run history cannot be used: %1

Runs are not recorded until this is fixed (Settings shows where the history is kept).</source>
        <translation>Историю серий невозможно использовать: %1

Серии не записываются, пока это не исправлено (на странице «Настройки» указано, где хранится история).</translation>
    </message>
</context>
<context>
    <name>tt::ui::HydraulicFeedTool</name>
    <message>
        <source>Hydraulic feed</source>
        <translation>Гидроподача</translation>
    </message>
    <message>
        <source>Sensor</source>
        <translation>Датчик</translation>
    </message>
    <message>
        <source>Amplifier</source>
        <translation>Усилитель</translation>
    </message>
    <message>
        <source>Electromagnet</source>
        <translation>Электромагнит</translation>
    </message>
    <message>
        <source>Spool</source>
        <translation>Золотник</translation>
    </message>
    <message>
        <source>Slot</source>
        <translation>Щель</translation>
    </message>
    <message>
        <source>Cylinder</source>
        <translation>Цилиндр</translation>
    </message>
    <message>
        <source>load P: leakage α₀ = k_y P/F</source>
        <translation>нагрузка P: утечки α₀ = k_y P/F</translation>
    </message>
    <message>
        <source>chip thickness: P_y = P (v/S)^%1</source>
        <translation>толщина среза: P_y = P (v/S)^%1</translation>
    </message>
    <message>
        <source>no loop: the force does not follow the feed (y = 0)</source>
        <translation>контура нет: сила не зависит от подачи (y = 0)</translation>
    </message>
    <message>
        <source>Load step</source>
        <translation>Нагрузка</translation>
    </message>
    <message>
        <source> N</source>
        <translation> Н</translation>
    </message>
    <message>
        <source>at</source>
        <translation>в</translation>
    </message>
    <message>
        <source> s</source>
        <translation> с</translation>
    </message>
    <message>
        <source>Simulate</source>
        <translation>Моделировать</translation>
    </message>
    <message>
        <source>Preset values</source>
        <translation>Из пресета</translation>
    </message>
    <message>
        <source>Sweep ξ</source>
        <translation>Перебор ξ</translation>
    </message>
    <message>
        <source>Sweep gain</source>
        <translation>Перебор K_a</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Отмена</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>Экспорт</translation>
    </message>
    <message>
        <source>PNG…</source>
        <translation>PNG…</translation>
    </message>
    <message>
        <source>CSV…</source>
        <translation>CSV…</translation>
    </message>
    <message>
        <source>The load step at %1 s comes after the end of the simulation (%2 s).</source>
        <translation>Скачок нагрузки в %1 с позже конца моделирования (%2 с).</translation>
    </message>
    <message>
        <source>A gain sweep needs a load: the gains are multiples of the one that makes up its leakage.</source>
        <translation>Для перебора усиления нужна нагрузка: усиления берутся кратными тому, что компенсирует её утечки.</translation>
    </message>
    <message>
        <source>Simulating with and without the regulator…</source>
        <translation>Моделирование с регулятором и без…</translation>
    </message>
    <message>
        <source>Sweeping ξ…</source>
        <translation>Перебор ξ…</translation>
    </message>
    <message>
        <source>Sweeping the gain…</source>
        <translation>Перебор усиления…</translation>
    </message>
    <message>
        <source>Cancelled; the curves shown are from the last finished run.</source>
        <translation>Отменено; показаны кривые последнего завершённого расчёта.</translation>
    </message>
    <message numerus="yes">
        <source>%n run(s) swept; settling times and overshoots are on the Sweep table tab.</source>
        <translation>
            <numerusform>Выполнен %n расчёт; время установления и перерегулирование — на вкладке «Таблица».</numerusform>
            <numerusform>Выполнено %n расчёта; время установления и перерегулирование — на вкладке «Таблица».</numerusform>
            <numerusform>Выполнено %n расчётов; время установления и перерегулирование — на вкладке «Таблица».</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>The spool swings past its final opening in %n of them.</source>
        <translation>
            <numerusform>Золотник проходит за установившееся открытие в %n из них.</numerusform>
            <numerusform>Золотник проходит за установившееся открытие в %n из них.</numerusform>
            <numerusform>Золотник проходит за установившееся открытие в %n из них.</numerusform>
        </translation>
    </message>
    <message>
        <source>Set a load first: the gain is designed to make up its leakage.</source>
        <translation>Сначала задайте нагрузку: усиление рассчитывается на компенсацию её утечек.</translation>
    </message>
    <message>
        <source>Gain %1 V/V and lap %2 mm: the slot opens by just the leakage of %3 N at the set feed.</source>
        <translation>Усиление %1 В/В и перекрытие %2 мм: щель открывается ровно на утечки от %3 Н при заданной подаче.</translation>
    </message>
    <message>
        <source>Choose a block on the diagram to edit its parameters, then Simulate.</source>
        <translation>Выберите блок на схеме, чтобы изменить его параметры, затем «Моделировать».</translation>
    </message>
    <message>
        <source>Stability boundary: K_a = %1 (%2 × the design gain %3); simulated at ±5 %: %4.</source>
        <translation>Граница устойчивости: K_a = %1 (%2 × расчётного %3); моделирование при ±5 %: %4.</translation>
    </message>
    <message>
        <source>confirmed</source>
        <translation>подтверждено</translation>
    </message>
    <message>
        <source>not confirmed</source>
        <translation>не подтверждено</translation>
    </message>
    <message>
        <source>No gain destabilises the chain; the slot opens fully above K_a = %1 (%2 × the design gain %3).</source>
        <translation>Никакое усиление не нарушает устойчивость; щель открывается полностью при K_a выше %1 (%2 × расчётного %3).</translation>
    </message>
    <message>
        <source>No gain up to 1e5 destabilises the chain (design gain %1).</source>
        <translation>Никакое усиление до 1e5 не нарушает устойчивость (расчётное %1).</translation>
    </message>
    <message>
        <source>Export the chart</source>
        <translation>Экспорт графика</translation>
    </message>
    <message>
        <source>PNG images (*.png)</source>
        <translation>Изображения PNG (*.png)</translation>
    </message>
    <message>
        <source>Cannot write %1.</source>
        <translation>Не удаётся записать %1.</translation>
    </message>
    <message>
        <source>Chart written to %1.</source>
        <translation>График записан в %1.</translation>
    </message>
    <message>
        <source>Export the curves</source>
        <translation>Экспорт кривых</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>Файлы CSV (*.csv)</translation>
    </message>
    <message>
        <source>Cannot write %1: %2</source>
        <translation>Не удаётся записать %1: %2</translation>
    </message>
    <message>
        <source>Curves written to %1.</source>
        <translation>Кривые записаны в %1.</translation>
    </message>
    <message numerus="yes">
        <source>%n run(s) beyond the stability boundary.</source>
        <translation>
            <numerusform>%n расчёт за границей устойчивости.</numerusform>
            <numerusform>%n расчёта за границей устойчивости.</numerusform>
            <numerusform>%n расчётов за границей устойчивости.</numerusform>
        </translation>
    </message>
    <message>
        <source>Regulator</source>
        <translation>Регулятор</translation>
    </message>
    <message>
        <source>Feedback of the feed</source>
        <translation>Обратная связь по подаче</translation>
    </message>
    <message>
        <source>Feed-forward of the force (paper)</source>
        <translation>Упреждение по силе (статья)</translation>
    </message>
    <message>
        <source>the feedback</source>
        <translation>обратной связью</translation>
    </message>
    <message>
        <source>the feed-forward</source>
        <translation>упреждением</translation>
    </message>
    <message>
        <source>Steady feed %1 mm/s with %7, %2 mm/s without (set %3). Settling (5 %): %4 s with, %5 s without; overshoot %6 %.</source>
        <translation>Установившаяся подача %1 мм/с с %7, %2 мм/с без регулятора (задано %3). Время установления (5 %): %4 с с регулятором, %5 с без; перерегулирование %6 %.</translation>
    </message>
    <message>
        <source>%1 (%2 dB) at %3 rad/s</source>
        <translation>%1 (%2 дБ) на %3 рад/с</translation>
    </message>
    <message>
        <source>unlimited</source>
        <translation>не ограничен</translation>
    </message>
    <message>
        <source>%1° at %2 rad/s</source>
        <translation>%1° на %2 рад/с</translation>
    </message>
    <message>
        <source>Margins of the feedback loop: gain %1, phase %2; closed loop %3.</source>
        <translation>Запасы контура обратной связи: по усилению %1, по фазе %2; замкнутый контур %3.</translation>
    </message>
    <message>
        <source>stable</source>
        <translation>устойчив</translation>
    </message>
    <message>
        <source>UNSTABLE</source>
        <translation>НЕУСТОЙЧИВ</translation>
    </message>
    <message>
        <source>The carriage stalled from %1 s to %2 s: the flow cannot make up the load&apos;s leakage.</source>
        <translation>Суппорт стоял с %1 с до %2 с: расход не покрывает утечку от нагрузки.</translation>
    </message>
    <message>
        <source>The slot was fully open from %1 s to %2 s: the regulator could give no more flow.</source>
        <translation>Щель была открыта полностью с %1 с до %2 с: регулятор не мог дать больше расхода.</translation>
    </message>
    <message>
        <source>The feedback asked for less than a shut slot from %1 s to %2 s.</source>
        <translation>Обратная связь требовала закрыть щель сильнее полного закрытия с %1 с до %2 с.</translation>
    </message>
    <message>
        <source>The feed ends %1 % off the set feed (band ±%2 %).</source>
        <translation>Подача в конце отличается от заданной на %1 % (допуск ±%2 %).</translation>
    </message>
    <message>
        <source>Without the regulator the carriage stalls: the pump&apos;s flow cannot make up the leakage.</source>
        <translation>Без регулятора суппорт стоит: расход насоса не покрывает утечку.</translation>
    </message>
</context>
<context>
    <name>tt::ui::InterruptedRun</name>
    <message>
        <source>no end</source>
        <translation>без конца</translation>
    </message>
    <message>
        <source>Run %1 (%2, %3, %4 of %5 parts done) was interrupted. Continue it from part %6?</source>
        <translation>Серия %1 (%2, %3, сделано %4 из %5 деталей) была прервана. Продолжить её с детали %6?</translation>
    </message>
    <message>
        <source>Interrupted run</source>
        <translation>Прерванная серия</translation>
    </message>
</context>
<context>
    <name>tt::ui::Kiosk</name>
    <message>
        <source>Quit the terminal</source>
        <translation>Выход из терминала</translation>
    </message>
    <message>
        <source>This terminal runs in kiosk mode: only an engineer may quit it.

Are you an engineer, and do you want to quit TrueTurn?</source>
        <translation>Терминал работает в режиме киоска: выйти из него может только инженер.

Вы инженер и хотите выйти из TrueTurn?</translation>
    </message>
</context>
<context>
    <name>tt::ui::KpCalibrationWizard</name>
    <message>
        <source>k_p from known loads</source>
        <translation>k_p по известным нагрузкам</translation>
    </message>
</context>
<context>
    <name>tt::ui::KpFitPage</name>
    <message>
        <source>Refused: %1</source>
        <translation>Отклонено: %1</translation>
    </message>
    <message>
        <source>known loads</source>
        <translation>известные нагрузки</translation>
    </message>
    <message>
        <source>k_p ΔI + offset</source>
        <translation>k_p ΔI + смещение</translation>
    </message>
    <message>
        <source>residual</source>
        <translation>остаток</translation>
    </message>
    <message>
        <source>Load against ΔI</source>
        <translation>Нагрузка в зависимости от ΔI</translation>
    </message>
    <message>
        <source>ΔI, A</source>
        <translation>ΔI, А</translation>
    </message>
    <message>
        <source>Load, N</source>
        <translation>Нагрузка, Н</translation>
    </message>
    <message>
        <source>Residuals</source>
        <translation>Остатки</translation>
    </message>
    <message>
        <source>Load − fit, N</source>
        <translation>Нагрузка − аппроксимация, Н</translation>
    </message>
    <message>
        <source>Not accepted: a verification load failed or is being measured. Measure it again, or go back to the loads.</source>
        <translation>Не принято: проверочная нагрузка не прошла проверку или ещё измеряется. Измерьте её заново или вернитесь к нагрузкам.</translation>
    </message>
    <message>
        <source>Check load</source>
        <translation>Проверить</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Стоп</translation>
    </message>
    <message>
        <source>Measuring the verification load…</source>
        <translation>Измерение проверочной нагрузки…</translation>
    </message>
    <message>
        <source>&lt;p&gt;&lt;b&gt;k_p = %1 N/A&lt;/b&gt; (offset %2 N, R² %3, residual RMS %4 N) from %5 loads.&lt;/p&gt;&lt;p&gt;The straight line P = k_p ΔI + offset is fitted by least squares; the offset should be small against the loads (it shows an asymmetry of the drive). Check it at a load not used in the fit before going on.&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;k_p = %1 Н/А&lt;/b&gt; (смещение %2 Н, R² %3, СКО остатков %4 Н), нагрузок: %5.&lt;/p&gt;&lt;p&gt;Прямая P = k_p ΔI + смещение строится методом наименьших квадратов; смещение должно быть малым по сравнению с нагрузками (оно показывает асимметрию привода). Перед продолжением проверьте её при нагрузке, не использованной в расчёте.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>Fit and verify k_p</source>
        <translation>Расчёт и проверка k_p</translation>
    </message>
    <message>
        <source>Force against the current difference, then a verification load not used in the fit.</source>
        <translation>Сила в зависимости от разности токов, затем проверочная нагрузка, не использованная в расчёте.</translation>
    </message>
    <message>
        <source>Verification load</source>
        <translation>Проверочная нагрузка</translation>
    </message>
    <message>
        <source> N</source>
        <translation> Н</translation>
    </message>
</context>
<context>
    <name>tt::ui::KpLoadsPage</name>
    <message>
        <source>measured, %1 pairs</source>
        <translation>измерено, пар ходов: %1</translation>
    </message>
    <message>
        <source>typed</source>
        <translation>вручную</translation>
    </message>
    <message>
        <source>known loads</source>
        <translation>известные нагрузки</translation>
    </message>
    <message>
        <source>Known loads</source>
        <translation>Известные нагрузки</translation>
    </message>
    <message>
        <source>Apply the load, enter what the gauge shows, measure. At least 3 loads, 0 included.</source>
        <translation>Приложите нагрузку, введите показание прибора, измерьте. Не менее 3 нагрузок, включая 0.</translation>
    </message>
    <message>
        <source>Known load</source>
        <translation>Известная нагрузка</translation>
    </message>
    <message>
        <source>Measure</source>
        <translation>Измерить</translation>
    </message>
    <message>
        <source>ΔI (typed)</source>
        <translation>ΔI (вручную)</translation>
    </message>
    <message>
        <source>Add typed point</source>
        <translation>Добавить точку вручную</translation>
    </message>
    <message>
        <source>Remove point</source>
        <translation>Удалить точку</translation>
    </message>
    <message>
        <source>Load, N</source>
        <translation>Нагрузка, Н</translation>
    </message>
    <message>
        <source>ΔI, A</source>
        <translation>ΔI, А</translation>
    </message>
    <message>
        <source>Source</source>
        <translation>Источник</translation>
    </message>
    <message>
        <source>Current difference against the load</source>
        <translation>Разность токов в зависимости от нагрузки</translation>
    </message>
    <message>
        <source> N</source>
        <translation> Н</translation>
    </message>
    <message>
        <source> A</source>
        <translation> А</translation>
    </message>
    <message>
        <source>No drive read-out: type the current differences</source>
        <translation>Нет датчика тока привода: введите разности токов вручную</translation>
    </message>
    <message>
        <source>Drive read-out: %1</source>
        <translation>Датчик тока привода: %1</translation>
    </message>
    <message>
        <source>Live ΔI %1 A (last stroke pair)</source>
        <translation>Текущая ΔI %1 А (последняя пара ходов)</translation>
    </message>
    <message>
        <source>Waiting for dither strokes…</source>
        <translation>Ожидание ходов колебаний…</translation>
    </message>
    <message>
        <source>Measuring at %1 N: keep the load steady while it settles…</source>
        <translation>Измерение при %1 Н: удерживайте нагрузку постоянной, пока всё успокаивается…</translation>
    </message>
    <message>
        <source>Measuring at %1 N: %2 stroke pairs averaged…</source>
        <translation>Измерение при %1 Н: усреднено пар ходов: %2…</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Стоп</translation>
    </message>
    <message>
        <source>The stand&apos;s hydraulic jack applies the load you enter. Measure at least 3 loads, 0 included.</source>
        <translation>Гидравлический домкрат стенда создаёт введённую нагрузку. Измерьте не менее 3 нагрузок, включая 0.</translation>
    </message>
    <message>
        <source>Repeat load</source>
        <translation>Повторить</translation>
    </message>
</context>
<context>
    <name>tt::ui::KpSavePage</name>
    <message>
        <source>Save k_p</source>
        <translation>Сохранение k_p</translation>
    </message>
    <message>
        <source>Enter your name on the Settings page first.</source>
        <translation>Сначала введите своё имя на странице «Настройки».</translation>
    </message>
    <message>
        <source>Not saved: no operator name (Settings).</source>
        <translation>Не сохранено: нет имени оператора («Настройки»).</translation>
    </message>
    <message>
        <source>The calibration database is not open.</source>
        <translation>База калибровок не открыта.</translation>
    </message>
    <message>
        <source>Not saved: %1</source>
        <translation>Не сохранено: %1</translation>
    </message>
    <message>
        <source>Saved. No tool was chosen, so the tool table is unchanged.</source>
        <translation>Сохранено. Инструмент не выбран, поэтому таблица инструментов не изменилась.</translation>
    </message>
    <message>
        <source>Saved; k_p %1 N/A written into %2 (recorded in the tool audit).</source>
        <translation>Сохранено; k_p %1 Н/А записан в %2 (отмечено в журнале изменений инструментов).</translation>
    </message>
    <message>
        <source>The calibration is kept with your name; the chosen tools get the new k_p.</source>
        <translation>Калибровка сохраняется с вашим именем; выбранные инструменты получают новый k_p.</translation>
    </message>
    <message>
        <source>Save and write into the tools</source>
        <translation>Сохранить и записать в инструменты</translation>
    </message>
    <message>
        <source>k_p = %1 N/A, to be written into: %2.</source>
        <translation>k_p = %1 Н/А, будет записан в: %2.</translation>
    </message>
    <message>
        <source>no tool (only the calibration is kept)</source>
        <translation>никуда (сохраняется только калибровка)</translation>
    </message>
</context>
<context>
    <name>tt::ui::KpSetupPage</name>
    <message>
        <source>%1 %2 — k_p now %3 N/A</source>
        <translation>%1 %2 — сейчас k_p %3 Н/А</translation>
    </message>
    <message>
        <source>Drive and tools</source>
        <translation>Привод и инструменты</translation>
    </message>
    <message>
        <source>k_p turns the cross-feed motor current into force: P = k_p (I_fwd − I_rev) / 2.</source>
        <translation>k_p пересчитывает ток двигателя поперечной подачи в силу: P = k_p (I_fwd − I_rev) / 2.</translation>
    </message>
    <message>
        <source>Cross-feed drive</source>
        <translation>Привод поперечной подачи</translation>
    </message>
    <message>
        <source>Write the new k_p into</source>
        <translation>Записать новый k_p в</translation>
    </message>
    <message>
        <source>Put a dynamometer or a hydraulic jack with a gauge between the tool block and the workpiece so it pushes the tool towards the axis like the cutting force. Start the cross-feed dither (as for boring) and keep it running; at each load the current is averaged at constant velocity in both directions.</source>
        <translation>Установите динамометр или гидравлический домкрат с манометром между резцедержателем и заготовкой так, чтобы он отжимал инструмент к оси, как сила резания. Включите дизеринг поперечной подачи (как при растачивании) и не выключайте его; при каждой нагрузке ток усредняется на постоянной скорости в обоих направлениях.</translation>
    </message>
</context>
<context>
    <name>tt::ui::LathePanel</name>
    <message>
        <source>No run on the lathe</source>
        <translation>Серия на станке не запущена</translation>
    </message>
    <message>
        <source>No part on the machine</source>
        <translation>На станке нет детали</translation>
    </message>
    <message>
        <source>Machine part %1</source>
        <translation>Обработайте деталь %1</translation>
    </message>
    <message>
        <source>Press Start: the corrections of part 1 go to the CNC.</source>
        <translation>Нажмите «Пуск»: коррекции детали 1 будут переданы в ЧПУ.</translation>
    </message>
    <message>
        <source>The next part starts when its corrections are on the CNC.</source>
        <translation>Следующая деталь начнётся, когда её коррекции будут в ЧПУ.</translation>
    </message>
    <message>
        <source>Its corrections are on the CNC.</source>
        <translation>Её коррекции переданы в ЧПУ.</translation>
    </message>
    <message>
        <source>Its corrections are on the CNC (%1).</source>
        <translation>Её коррекции переданы в ЧПУ (%1).</translation>
    </message>
    <message>
        <source>Nothing to measure</source>
        <translation>Измерять нечего</translation>
    </message>
    <message>
        <source>Part %1: type its diameters below</source>
        <translation>Деталь %1: введите её диаметры ниже</translation>
    </message>
    <message>
        <source>Measure part %1 at x = %2 mm</source>
        <translation>Измерьте деталь %1 в точке x = %2 мм</translation>
    </message>
    <message>
        <source>Point %1 of %2</source>
        <translation>Точка %1 из %2</translation>
    </message>
    <message>
        <source>%1 · last reading %2</source>
        <translation>%1 · последнее показание %2</translation>
    </message>
    <message>
        <source>Take gauge reading</source>
        <translation>Снять показание</translation>
    </message>
    <message>
        <source>Part %1 finished</source>
        <translation>Деталь %1 готова</translation>
    </message>
    <message>
        <source>Part finished</source>
        <translation>Деталь готова</translation>
    </message>
</context>
<context>
    <name>tt::ui::LoginDialog</name>
    <message>
        <source>Log in</source>
        <translation>Войти</translation>
    </message>
    <message>
        <source>Log in to TrueTurn</source>
        <translation>Вход в TrueTurn</translation>
    </message>
    <message>
        <source>Password or PIN</source>
        <translation>Пароль или PIN</translation>
    </message>
    <message>
        <source>User</source>
        <translation>Пользователь</translation>
    </message>
    <message>
        <source>Quit</source>
        <translation>Выйти</translation>
    </message>
    <message>
        <source>Clear</source>
        <translation>Сброс</translation>
    </message>
    <message numerus="yes">
        <source>Wrong name or password. %n attempt(s) left before the lock-out.</source>
        <translation>
            <numerusform>Неверное имя или пароль. До блокировки осталась %n попытка.</numerusform>
            <numerusform>Неверное имя или пароль. До блокировки осталось %n попытки.</numerusform>
            <numerusform>Неверное имя или пароль. До блокировки осталось %n попыток.</numerusform>
        </translation>
    </message>
    <message>
        <source>Too many failed log-ins: %1 is locked until %2. An administrator can unlock it.</source>
        <translation>Слишком много неудачных попыток входа: %1 заблокирован до %2. Разблокировать может администратор.</translation>
    </message>
    <message>
        <source>Cannot log in: %1</source>
        <translation>Не удаётся войти: %1</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Отмена</translation>
    </message>
</context>
<context>
    <name>tt::ui::MainWindow</name>
    <message>
        <source>About TrueTurn</source>
        <translation>О программе TrueTurn</translation>
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
    <message>
        <source>a run is going (loop: %1); quitting stops it, its finished parts stay in the history</source>
        <translation>идёт работа (контур: %1); выход остановит её, готовые детали останутся в истории</translation>
    </message>
    <message>
        <source>%1 not applied; quitting discards them</source>
        <translation>%1 — не применены; при выходе они пропадут</translation>
    </message>
    <message>
        <source>Quit TrueTurn?</source>
        <translation>Выйти из TrueTurn?</translation>
    </message>
    <message>
        <source>Before you quit:
• %1

Quit anyway?</source>
        <translation>Перед выходом:
• %1

Всё равно выйти?</translation>
    </message>
    <message>
        <source>On-screen &amp;keypad</source>
        <translation>Экранная &amp;клавиатура</translation>
    </message>
    <message>
        <source>&amp;Sound on rework or scrap</source>
        <translation>&amp;Звук при доработке или браке</translation>
    </message>
</context>
<context>
    <name>tt::ui::ManualEntryPanel</name>
    <message>
        <source>Part %1 by hand: diameters in mm, nominal %2, Enter for the next point</source>
        <translation>Деталь %1 вручную: диаметры в мм, номинал %2, Enter — следующая точка</translation>
    </message>
    <message>
        <source>By hand: no part is waiting for its diameters</source>
        <translation>Вручную: ни одна деталь не ожидает ввода диаметров</translation>
    </message>
    <message>
        <source>x = %1 mm</source>
        <translation>x = %1 мм</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a diameter in mm.</source>
        <translation>«%1» — не диаметр в мм.</translation>
    </message>
    <message>
        <source>Rejected: %1</source>
        <translation>Отклонено: %1</translation>
    </message>
    <message>
        <source>Point %1: %2</source>
        <translation>Точка %1: %2</translation>
    </message>
    <message>
        <source>No part is waiting for its diameters: nothing was sent.</source>
        <translation>Ни одна деталь не ожидает ввода диаметров: ничего не отправлено.</translation>
    </message>
</context>
<context>
    <name>tt::ui::MaterialsModel</name>
    <message>
        <source>Material</source>
        <translation>Материал</translation>
    </message>
    <message>
        <source>Young&apos;s modulus E, MPa</source>
        <translation>Модуль Юнга E, МПа</translation>
    </message>
    <message>
        <source>material: the name must not be empty</source>
        <translation>материал: название не может быть пустым</translation>
    </message>
    <message>
        <source>Young&apos;s modulus E: &apos;%1&apos; must be a number between %2 and %3 MPa</source>
        <translation>Модуль Юнга E: «%1» должен быть числом от %2 до %3 МПа</translation>
    </message>
</context>
<context>
    <name>tt::ui::MeasurementsModel</name>
    <message>
        <source>—</source>
        <translation>—</translation>
    </message>
    <message>
        <source>accepted</source>
        <translation>принято</translation>
    </message>
    <message>
        <source>rejected</source>
        <translation>отклонено</translation>
    </message>
    <message>
        <source>not measured</source>
        <translation>не измерено</translation>
    </message>
    <message>
        <source>Part</source>
        <translation>Деталь</translation>
    </message>
    <message>
        <source>Point</source>
        <translation>Точка</translation>
    </message>
    <message>
        <source>x, mm</source>
        <translation>x, мм</translation>
    </message>
    <message>
        <source>Measured, mm</source>
        <translation>Измерено, мм</translation>
    </message>
    <message>
        <source>Nominal, mm</source>
        <translation>Номинал, мм</translation>
    </message>
    <message>
        <source>Deviation, mm</source>
        <translation>Отклонение, мм</translation>
    </message>
    <message>
        <source>Verdict</source>
        <translation>Решение</translation>
    </message>
    <message>
        <source>Reason</source>
        <translation>Причина</translation>
    </message>
    <message>
        <source>Correction, mm</source>
        <translation>Коррекция, мм</translation>
    </message>
</context>
<context>
    <name>tt::ui::MeasurementsPage</name>
    <message>
        <source>Run</source>
        <translation>Серия</translation>
    </message>
    <message>
        <source>Only rejected and unmeasured</source>
        <translation>Только непринятые значения</translation>
    </message>
    <message>
        <source>Refresh</source>
        <translation>Обновить</translation>
    </message>
    <message>
        <source>The run history cannot be read</source>
        <translation>Не удаётся прочитать историю серий</translation>
    </message>
    <message>
        <source>No parts recorded yet</source>
        <translation>Детали ещё не записаны</translation>
    </message>
    <message>
        <source>Start a run on the Run page: every measured part appears here with its diameters at the control points, whether each was accepted and why not.</source>
        <translation>Запустите серию на странице «Работа»: здесь появится каждая измеренная деталь с диаметрами в контрольных точках — принят ли каждый из них, а если нет, то почему.</translation>
    </message>
    <message>
        <source>Run %1 · %2 · %3, z = %4 · %5 parts · %6</source>
        <translation>Серия %1 · %2 · %3, z = %4 · %5 дет. · %6</translation>
    </message>
    <message>
        <source>%1 parts recorded, %2 measured; %3 values rejected or not measured.</source>
        <translation>Записано деталей: %1, измерено: %2; отклонено или не измерено значений: %3.</translation>
    </message>
    <message>
        <source>LQG</source>
        <translation>ЛКГ</translation>
    </message>
    <message>
        <source>EWMA</source>
        <translation>EWMA</translation>
    </message>
    <message>
        <source>open loop</source>
        <translation>без регулятора</translation>
    </message>
    <message>
        <source>complete</source>
        <translation>завершена</translation>
    </message>
    <message>
        <source>stopped</source>
        <translation>остановлена</translation>
    </message>
    <message>
        <source>not finished</source>
        <translation>не завершена</translation>
    </message>
</context>
<context>
    <name>tt::ui::NumericKeypad</name>
    <message>
        <source>Enter a number</source>
        <translation>Введите число</translation>
    </message>
    <message>
        <source>Clear</source>
        <translation>Сброс</translation>
    </message>
    <message>
        <source>OK</source>
        <translation>ОК</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Отмена</translation>
    </message>
    <message>
        <source>Limits: %1 … %2</source>
        <translation>Пределы: %1 … %2</translation>
    </message>
    <message>
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
    <message>
        <source>Type a number first.</source>
        <translation>Сначала введите число.</translation>
    </message>
    <message>
        <source>%1 is outside the limits (%2).</source>
        <translation>%1 вне пределов (%2).</translation>
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
        <source>Gauge micrometer, probe mandrel, drive-current readout and the correction output to the CNC; the built-in simulator is always available.</source>
        <translation>Цифровой микрометр, оправка-датчик, считывание тока привода и вывод коррекции в ЧПУ; встроенный симулятор доступен всегда.</translation>
    </message>
    <message>
        <source>Process</source>
        <translation>Технология</translation>
    </message>
    <message>
        <source>Plant</source>
        <translation>Цех</translation>
    </message>
</context>
<context>
    <name>tt::ui::PlantModel</name>
    <message>
        <source>running</source>
        <translation>работает</translation>
    </message>
    <message>
        <source>offline</source>
        <translation>нет связи</translation>
    </message>
    <message>
        <source>offline, last part %1</source>
        <translation>нет связи, последняя деталь %1</translation>
    </message>
    <message>
        <source>idle</source>
        <translation>простаивает</translation>
    </message>
    <message>
        <source>idle, last part %1</source>
        <translation>простаивает, последняя деталь %1</translation>
    </message>
    <message>
        <source>Cpk of the last %1 parts; %2 parts before: %3</source>
        <translation>Cpk последних %1 деталей; %2 деталей до них: %3</translation>
    </message>
    <message>
        <source>Machine</source>
        <translation>Станок</translation>
    </message>
    <message>
        <source>State</source>
        <translation>Состояние</translation>
    </message>
    <message>
        <source>Kept on
terminal</source>
        <translation>Хранится
на терминале</translation>
    </message>
    <message>
        <source>Today
good / rework / scrap</source>
        <translation>Сегодня
годные / доработка / брак</translation>
    </message>
    <message>
        <source>Alarms</source>
        <translation>Тревоги</translation>
    </message>
    <message>
        <source>Cpk
point %1</source>
        <translation>Cpk
точка %1</translation>
    </message>
</context>
<context>
    <name>tt::ui::PlantPage</name>
    <message>
        <source>Refresh</source>
        <translation>Обновить</translation>
    </message>
    <message>
        <source>Click a machine to open its reports. Cpk of the last %1 parts per control point, ▲▼ its change against the %1 before; the page reads the plant database every %2 s.</source>
        <translation>Нажмите на станок, чтобы открыть его отчёты. Cpk последних %1 деталей по каждой контрольной точке, ▲▼ — изменение относительно %1 деталей до них; страница читает базу цеха каждые %2 с.</translation>
    </message>
    <message>
        <source>none</source>
        <translation>нет</translation>
    </message>
    <message>
        <source>Plant database: %1</source>
        <translation>База цеха: %1</translation>
    </message>
    <message>
        <source>No machine has written to the plant database yet</source>
        <translation>Ни один станок ещё не писал в базу цеха</translation>
    </message>
    <message>
        <source>Every terminal that stores its runs here appears with its state, the parts it still keeps, today&apos;s verdicts, the capability of its last parts and its open alarms.</source>
        <translation>Каждый терминал, который хранит здесь свои работы, появится с состоянием, деталями, которые он ещё хранит у себя, сегодняшними заключениями, воспроизводимостью последних деталей и открытыми тревогами.</translation>
    </message>
    <message>
        <source>Reading the plant database…</source>
        <translation>Чтение базы цеха…</translation>
    </message>
    <message>
        <source>Cannot read the plant database: %1</source>
        <translation>Не удаётся прочитать базу цеха: %1</translation>
    </message>
    <message numerus="yes">
        <source>Read at %1: %n machine(s)</source>
        <translation>
            <numerusform>Прочитано в %1: %n станок</numerusform>
            <numerusform>Прочитано в %1: %n станка</numerusform>
            <numerusform>Прочитано в %1: %n станков</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>tt::ui::ProbeAcceptPage</name>
    <message>
        <source>(typed points)</source>
        <translation>(точки введены вручную)</translation>
    </message>
    <message>
        <source>&lt;p&gt;Characteristic of degree %1 from %2 points, residual RMS %3 µm.&lt;/p&gt;&lt;p&gt;Table: %4 entries of %5 nm, worst error at the calibration points %6 µm, step between codes up to %7 µm; %8 entries outside the calibrated range %9 .. %10 µm are extrapolated.%11&lt;/p&gt;&lt;p&gt;It will be saved as version &lt;b&gt;%12&lt;/b&gt; of %13, plane %14, by &lt;b&gt;%15&lt;/b&gt;.&lt;/p&gt;</source>
        <translation>&lt;p&gt;Характеристика степени %1, точек: %2, СКО остатков %3 мкм.&lt;/p&gt;&lt;p&gt;Таблица: значений %4, дискретность %5 нм, наибольшая погрешность в точках калибровки %6 мкм, шаг между кодами до %7 мкм; экстраполировано значений вне калиброванного диапазона %9 .. %10 мкм: %8.%11&lt;/p&gt;&lt;p&gt;Она будет сохранена как версия &lt;b&gt;%12&lt;/b&gt; для «%13», плоскость %14, оператор &lt;b&gt;%15&lt;/b&gt;.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>(no operator name — set it in Settings)</source>
        <translation>(нет имени оператора — укажите его в «Настройках»)</translation>
    </message>
    <message>
        <source>I accept this linearisation table</source>
        <translation>Принимаю эту таблицу линеаризации</translation>
    </message>
    <message>
        <source>Hold still, then the live codes are averaged…</source>
        <translation>Оправка успокаивается, затем коды усредняются…</translation>
    </message>
    <message>
        <source>Not accepted: a verification point failed or is being read. Check again, or go back and capture more points.</source>
        <translation>Не принято: проверочная точка не прошла проверку или ещё снимается. Проверьте снова или вернитесь и снимите больше точек.</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Стоп</translation>
    </message>
    <message>
        <source>Check point</source>
        <translation>Проверить</translation>
    </message>
    <message>
        <source>%1 % of the table lies outside the calibrated range and is extrapolated; calibrate over more of the probe&apos;s travel.</source>
        <translation>%1 % таблицы лежит вне калиброванного диапазона и экстраполировано; калибруйте по большей части хода датчика.</translation>
    </message>
    <message>
        <source>no verification point yet</source>
        <translation>проверочных точек пока нет</translation>
    </message>
    <message>
        <source>%1 of %2 verification points passed</source>
        <translation>пройдено проверочных точек: %1 из %2</translation>
    </message>
    <message>
        <source>Verify the table — %1</source>
        <translation>Проверка таблицы — %1</translation>
    </message>
    <message>
        <source>Verify and accept the table</source>
        <translation>Проверка и принятие таблицы</translation>
    </message>
    <message>
        <source>Load the bar to a deflection not captured and check that the table reads it; the table is stored only when you accept it.</source>
        <translation>Нагрузите оправку до прогиба, которого нет среди точек, и проверьте, что таблица его показывает; таблица сохраняется, только когда вы её примете.</translation>
    </message>
    <message>
        <source>Stand&apos;s screw jack</source>
        <translation>Домкрат стенда</translation>
    </message>
    <message>
        <source>Bend the bar</source>
        <translation>Изогнуть оправку</translation>
    </message>
    <message>
        <source>Reference reading</source>
        <translation>Показание эталона</translation>
    </message>
    <message>
        <source> µm</source>
        <translation> мкм</translation>
    </message>
</context>
<context>
    <name>tt::ui::ProbeCalibrationWizard</name>
    <message>
        <source>Probe mandrel linearisation</source>
        <translation>Линеаризация оправки-датчика</translation>
    </message>
</context>
<context>
    <name>tt::ui::ProbeCapturePage</name>
    <message>
        <source>Probe: %1</source>
        <translation>Оправка: %1</translation>
    </message>
    <message>
        <source>Live ADC code %1 (mean of %2)</source>
        <translation>Текущий код АЦП %1 (среднее, отсчётов: %2)</translation>
    </message>
    <message>
        <source>Waiting for probe samples…</source>
        <translation>Ожидание отсчётов датчика…</translation>
    </message>
    <message>
        <source>now</source>
        <translation>сейчас</translation>
    </message>
    <message>
        <source>live, %1 samples</source>
        <translation>с датчика, отсчётов: %1</translation>
    </message>
    <message>
        <source>typed</source>
        <translation>вручную</translation>
    </message>
    <message>
        <source>captured</source>
        <translation>снятые точки</translation>
    </message>
    <message>
        <source>Capture points</source>
        <translation>Снятие точек</translation>
    </message>
    <message>
        <source>Bend the bar</source>
        <translation>Изогнуть оправку</translation>
    </message>
    <message>
        <source>Reference reading</source>
        <translation>Показание эталона</translation>
    </message>
    <message>
        <source>Capture point</source>
        <translation>Снять точку</translation>
    </message>
    <message>
        <source>ADC code (typed)</source>
        <translation>Код АЦП (вручную)</translation>
    </message>
    <message>
        <source>Add typed point</source>
        <translation>Добавить точку вручную</translation>
    </message>
    <message>
        <source>Remove point</source>
        <translation>Удалить точку</translation>
    </message>
    <message>
        <source>Reference, µm</source>
        <translation>Эталон, мкм</translation>
    </message>
    <message>
        <source>ADC code</source>
        <translation>Код АЦП</translation>
    </message>
    <message>
        <source>Source</source>
        <translation>Источник</translation>
    </message>
    <message>
        <source>ADC code against the reference deflection</source>
        <translation>Код АЦП в зависимости от эталонного прогиба</translation>
    </message>
    <message>
        <source>Reference deflection, µm</source>
        <translation>Эталонный прогиб, мкм</translation>
    </message>
    <message>
        <source>Captured points stay here when you go back or cancel.</source>
        <translation>Снятые точки сохраняются, если вернуться назад или отменить.</translation>
    </message>
    <message>
        <source> µm</source>
        <translation> мкм</translation>
    </message>
    <message>
        <source>No probe: type the points</source>
        <translation>Нет датчика: введите точки вручную</translation>
    </message>
    <message>
        <source>Live ADC code %1 (mean of %2) — at the ADC&apos;s limit</source>
        <translation>Текущий код АЦП %1 (среднее, отсчётов: %2) — на пределе АЦП</translation>
    </message>
    <message>
        <source>Hold still: the bar settles…</source>
        <translation>Не двигайте: оправка успокаивается…</translation>
    </message>
    <message>
        <source>Averaging the live codes at %1 µm…</source>
        <translation>Усреднение кодов при %1 мкм…</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Стоп</translation>
    </message>
    <message>
        <source>The jack bends the bar by at most ±2000 µm.</source>
        <translation>Домкрат изгибает оправку не более чем на ±2000 мкм.</translation>
    </message>
    <message>
        <source>The jack bends the bar to %1 µm; capture when the live code is steady.</source>
        <translation>Домкрат изгибает оправку до %1 мкм; снимите точку, когда текущий код установится.</translation>
    </message>
    <message>
        <source>No probe mandrel to read: type the point instead.</source>
        <translation>Нет оправки-датчика для считывания: введите точку вручную.</translation>
    </message>
    <message>
        <source>The typed code is outside the ADC&apos;s range.</source>
        <translation>Введённый код вне диапазона АЦП.</translation>
    </message>
    <message>
        <source>%1 — ADC saturated (%2 to %3 of 0 to %4), not used</source>
        <translation>%1 — АЦП в насыщении (%2–%3 при 0–%4), не используется</translation>
    </message>
    <message>
        <source>ADC saturated</source>
        <translation>АЦП в насыщении</translation>
    </message>
    <message>
        <source>Load the bar, read the instrument, capture: the bar holds still, then the codes are averaged. At least %1 points; both directions.</source>
        <translation>Нагрузите оправку, снимите показание прибора, зафиксируйте точку: оправка успокаивается, затем коды усредняются. Минимум точек: %1, в обоих направлениях.</translation>
    </message>
    <message>
        <source>Stand&apos;s screw jack</source>
        <translation>Домкрат стенда</translation>
    </message>
    <message>
        <source>Repeat point</source>
        <translation>Повторить</translation>
    </message>
</context>
<context>
    <name>tt::ui::ProbeChoosePage</name>
    <message>
        <source>No probe mandrel is configured: add one on the Devices page, or type the points.</source>
        <translation>Оправка-датчик не настроена: добавьте её на странице «Устройства» или вводите точки вручную.</translation>
    </message>
    <message>
        <source>%1 is ready.</source>
        <translation>%1: готово.</translation>
    </message>
    <message>
        <source>%1: %2 — you can still type the points by hand.</source>
        <translation>%1: %2 — точки можно ввести вручную.</translation>
    </message>
    <message>
        <source>Probe and bending plane</source>
        <translation>Оправка и плоскость изгиба</translation>
    </message>
    <message>
        <source>Which probe mandrel is calibrated, in which plane, and its ADC resolution.</source>
        <translation>Какая оправка-датчик калибруется, в какой плоскости, и разрядность её АЦП.</translation>
    </message>
    <message>
        <source>Probe mandrel</source>
        <translation>Оправка-датчик</translation>
    </message>
    <message>
        <source>Bending plane</source>
        <translation>Плоскость изгиба</translation>
    </message>
    <message>
        <source>ADC resolution</source>
        <translation>Разрядность АЦП</translation>
    </message>
    <message>
        <source>X — radial (bore diameter)</source>
        <translation>X — радиальная (диаметр отверстия)</translation>
    </message>
    <message>
        <source>Y — tangential</source>
        <translation>Y — тангенциальная</translation>
    </message>
    <message>
        <source> bit</source>
        <translation> бит</translation>
    </message>
</context>
<context>
    <name>tt::ui::ProbeFitPage</name>
    <message>
        <source>degree %1: leave-one-out %2 µm, in-sample %3 µm%4</source>
        <translation>степень %1: скользящий контроль %2 мкм, по самим точкам %3 мкм%4</translation>
    </message>
    <message>
        <source> — chosen</source>
        <translation> — выбрана</translation>
    </message>
    <message>
        <source>Refused: %1</source>
        <translation>Отклонено: %1</translation>
    </message>
    <message>
        <source>&lt;p style=&apos;color:#1b5e20&apos;&gt;&lt;b&gt;Monotonic over the whole ADC range; residual RMS %1 µm.&lt;/b&gt;&lt;/p&gt;</source>
        <translation>&lt;p style=&apos;color:#1b5e20&apos;&gt;&lt;b&gt;Монотонна во всём диапазоне АЦП; СКО остатков %1 мкм.&lt;/b&gt;&lt;/p&gt;</translation>
    </message>
    <message>
        <source>captured</source>
        <translation>снятые точки</translation>
    </message>
    <message>
        <source>fitted, degree %1</source>
        <translation>аппроксимация, степень %1</translation>
    </message>
    <message>
        <source>residual</source>
        <translation>остаток</translation>
    </message>
    <message>
        <source>zero</source>
        <translation>ноль</translation>
    </message>
    <message>
        <source>Fit the characteristic</source>
        <translation>Аппроксимация характеристики</translation>
    </message>
    <message>
        <source>The inductive sensor&apos;s characteristic is a polynomial of degree 2 to 4; the table inverts it.</source>
        <translation>Характеристика индуктивного датчика — полином степени от 2 до 4; таблица задаёт обратную функцию.</translation>
    </message>
    <message>
        <source>Degree</source>
        <translation>Степень</translation>
    </message>
    <message>
        <source>Automatic (cross-validation)</source>
        <translation>Автоматически (перекрёстная проверка)</translation>
    </message>
    <message>
        <source>2</source>
        <translation>2</translation>
    </message>
    <message>
        <source>3</source>
        <translation>3</translation>
    </message>
    <message>
        <source>4</source>
        <translation>4</translation>
    </message>
    <message>
        <source>Characteristic</source>
        <translation>Характеристика</translation>
    </message>
    <message>
        <source>Reference deflection, µm</source>
        <translation>Эталонный прогиб, мкм</translation>
    </message>
    <message>
        <source>ADC code</source>
        <translation>Код АЦП</translation>
    </message>
    <message>
        <source>Residuals</source>
        <translation>Остатки</translation>
    </message>
    <message>
        <source>Table reading − reference, µm</source>
        <translation>Показание по таблице − эталон, мкм</translation>
    </message>
    <message>
        <source>Each point is predicted from a fit to the others (leave-one-out); a higher degree always fits the points themselves better, so it is kept only when it predicts them better.</source>
        <translation>Каждая точка предсказывается по аппроксимации остальных (скользящий контроль); более высокая степень всегда лучше проходит через сами точки, поэтому она выбирается, только если лучше их предсказывает.</translation>
    </message>
</context>
<context>
    <name>tt::ui::ProbeReferencePage</name>
    <message>
        <source>Set up the reference</source>
        <translation>Установка эталона</translation>
    </message>
    <message>
        <source>The deflection is read on an instrument at the tool tip while the bar is loaded.</source>
        <translation>Прогиб отсчитывается по прибору у вершины резца при нагруженной оправке.</translation>
    </message>
    <message>
        <source>Reference instrument</source>
        <translation>Эталонный прибор</translation>
    </message>
    <message>
        <source>Dial indicator</source>
        <translation>Индикатор часового типа</translation>
    </message>
    <message>
        <source>Micrometer</source>
        <translation>Микрометр</translation>
    </message>
    <message>
        <source>Division of the instrument</source>
        <translation>Цена деления прибора</translation>
    </message>
    <message>
        <source>1. Clamp the boring bar as for cutting; mount the instrument on the lathe bed touching the tool tip in the chosen plane.
2. With the bar unloaded, set the instrument to zero.
3. Load the bar in both directions in steps (a screw jack against the tool block) over the whole travel of the probe; at each step read the instrument and capture the point. Aim for 15 to 25 points, both signs.</source>
        <translation>1. Закрепите расточную оправку как для резания; установите прибор на станине так, чтобы он касался вершины резца в выбранной плоскости.
2. При ненагруженной оправке установите прибор на ноль.
3. Нагружайте оправку ступенями в обоих направлениях (винтовым домкратом, упёртым в резцедержатель) на весь ход датчика; на каждой ступени снимите показание прибора и зафиксируйте точку. Желательно 15–25 точек обоих знаков.</translation>
    </message>
    <message>
        <source> µm</source>
        <translation> мкм</translation>
    </message>
</context>
<context>
    <name>tt::ui::ProbeSavePage</name>
    <message>
        <source>Export the table</source>
        <translation>Экспорт таблицы</translation>
    </message>
    <message>
        <source>C header (*.h);;Binary image (*.bin);;CSV (*.csv)</source>
        <translation>Заголовочный файл C (*.h);;Двоичный образ (*.bin);;CSV (*.csv)</translation>
    </message>
    <message>
        <source>The calibration database is not open; export the table instead.</source>
        <translation>База калибровок не открыта; экспортируйте таблицу в файл.</translation>
    </message>
    <message>
        <source>Save the table</source>
        <translation>Сохранение таблицы</translation>
    </message>
    <message>
        <source>Enter your name on the Settings page first: the table is saved with it.</source>
        <translation>Сначала введите своё имя на странице «Настройки»: таблица сохраняется вместе с ним.</translation>
    </message>
    <message>
        <source>Not saved: no operator name (Settings).</source>
        <translation>Не сохранено: нет имени оператора («Настройки»).</translation>
    </message>
    <message>
        <source>(typed points)</source>
        <translation>(точки введены вручную)</translation>
    </message>
    <message>
        <source>Not saved: %1</source>
        <translation>Не сохранено: %1</translation>
    </message>
    <message>
        <source>Saved as version %1 of %2 by %3 at %4.</source>
        <translation>Сохранено как версия %1 для «%2», оператор %3, %4.</translation>
    </message>
    <message>
        <source>Now upload it to the mandrel.</source>
        <translation>Теперь загрузите её в оправку.</translation>
    </message>
    <message>
        <source>Cannot write %1: %2</source>
        <translation>Не удаётся записать %1: %2</translation>
    </message>
    <message>
        <source>Exported to %1.</source>
        <translation>Экспортировано в %1.</translation>
    </message>
    <message>
        <source>Save and upload</source>
        <translation>Сохранение и загрузка</translation>
    </message>
    <message>
        <source>The table is saved as a new version with your name, then sent to the mandrel and read back.</source>
        <translation>Таблица сохраняется как новая версия с вашим именем, затем передаётся в оправку и считывается обратно для контроля.</translation>
    </message>
    <message>
        <source>Save the table, then upload it to %1. Finish is possible once the mandrel reports the same version and CRC as the image sent.</source>
        <translation>Сохраните таблицу, затем загрузите её в «%1». Завершить можно, когда оправка сообщит ту же версию и CRC, что у отправленного образа.</translation>
    </message>
    <message>
        <source>This probe takes no uploads here: save the table and export it for the microcontroller (C header or binary image).</source>
        <translation>Этот датчик не принимает загрузку отсюда: сохраните таблицу и экспортируйте её для микроконтроллера (заголовочный файл C или двоичный образ).</translation>
    </message>
    <message>
        <source>Save table</source>
        <translation>Сохранить таблицу</translation>
    </message>
    <message>
        <source>Upload to the mandrel</source>
        <translation>Загрузить в оправку</translation>
    </message>
    <message>
        <source>Export…</source>
        <translation>Экспорт…</translation>
    </message>
</context>
<context>
    <name>tt::ui::ProcessPage</name>
    <message>
        <source>Process design</source>
        <translation>Технологическая подготовка</translation>
    </message>
    <message>
        <source>Feed scheduling against force deformation with its CNC program, the corrective pulse of the feed drives at corners, and hydraulic feed stabilisation.</source>
        <translation>Программирование подачи по силовой деформации с управляющей программой ЧПУ, корректирующий импульс приводов подач на углах траектории и гидравлическая стабилизация подачи.</translation>
    </message>
</context>
<context>
    <name>tt::ui::ProfilePanel</name>
    <message>
        <source>Last part: diameter error along the shaft</source>
        <translation>Последняя деталь: погрешность диаметра по длине вала</translation>
    </message>
    <message>
        <source>x along the shaft, mm</source>
        <translation>x по длине вала, мм</translation>
    </message>
    <message>
        <source>diameter error, mm</source>
        <translation>погрешность Ø, мм</translation>
    </message>
    <message>
        <source>Error at the points, last %1 parts</source>
        <translation>Погрешность в точках, посл. %1 дет.</translation>
    </message>
    <message>
        <source>part</source>
        <translation>деталь</translation>
    </message>
    <message>
        <source>tolerance ±%1</source>
        <translation>допуск ±%1</translation>
    </message>
    <message>
        <source>model d(x)</source>
        <translation>модель d(x)</translation>
    </message>
    <message>
        <source>correction, part %1</source>
        <translation>коррекция, деталь %1</translation>
    </message>
    <message>
        <source>part %1 gauged</source>
        <translation>деталь %1, измерено</translation>
    </message>
    <message>
        <source>between points</source>
        <translation>между точками</translation>
    </message>
    <message>
        <source>x = %1</source>
        <translation>x = %1</translation>
    </message>
    <message>
        <source>tolerance</source>
        <translation>допуск</translation>
    </message>
    <message>
        <source>true profile</source>
        <translation>истинный профиль</translation>
    </message>
</context>
<context>
    <name>tt::ui::ReportFilterBar</name>
    <message>
        <source>all machines</source>
        <translation>все станки</translation>
    </message>
    <message>
        <source>all runs</source>
        <translation>все серии</translation>
    </message>
    <message numerus="yes">
        <source>Run %1 · %2 · %n parts</source>
        <translation>
            <numerusform>Серия %1 · %2 · %n деталь</numerusform>
            <numerusform>Серия %1 · %2 · %n детали</numerusform>
            <numerusform>Серия %1 · %2 · %n деталей</numerusform>
        </translation>
    </message>
    <message>
        <source>Machine</source>
        <translation>Станок</translation>
    </message>
    <message>
        <source>Run</source>
        <translation>Серия</translation>
    </message>
    <message>
        <source>From</source>
        <translation>С</translation>
    </message>
    <message>
        <source>To</source>
        <translation>По</translation>
    </message>
    <message>
        <source>Subgroup, parts</source>
        <translation>Подгруппа, деталей</translation>
    </message>
    <message>
        <source>Chart</source>
        <translation>Карта</translation>
    </message>
    <message>
        <source>Limits from first</source>
        <translation>Границы по первым</translation>
    </message>
    <message>
        <source>any date</source>
        <translation>любая дата</translation>
    </message>
    <message>
        <source>all points</source>
        <translation>все точки</translation>
    </message>
    <message>
        <source>by subgroup size</source>
        <translation>по размеру подгруппы</translation>
    </message>
    <message>
        <source>X̄-R</source>
        <translation>X̄-R</translation>
    </message>
    <message>
        <source>X̄-s</source>
        <translation>X̄-s</translation>
    </message>
    <message>
        <source>I-MR</source>
        <translation>I-MR</translation>
    </message>
</context>
<context>
    <name>tt::ui::ReportViews</name>
    <message numerus="yes">
        <source>Rule violations (Western Electric): %n</source>
        <translation>
            <numerusform>Нарушения правил (WE): %n</numerusform>
            <numerusform>Нарушения правил (WE): %n</numerusform>
            <numerusform>Нарушения правил (WE): %n</numerusform>
        </translation>
    </message>
    <message>
        <source>run %1, part %2</source>
        <translation>серия %1, деталь %2</translation>
    </message>
    <message>
        <source>Profile of %1</source>
        <translation>Профиль: %1</translation>
    </message>
    <message>
        <source>Control chart</source>
        <translation>Контрольная карта</translation>
    </message>
    <message>
        <source>Distribution and capability</source>
        <translation>Распределение и воспроизводимость</translation>
    </message>
    <message>
        <source>Part profile</source>
        <translation>Профиль детали</translation>
    </message>
    <message>
        <source>All points</source>
        <translation>Все точки</translation>
    </message>
    <message>
        <source>Point</source>
        <translation>Точка</translation>
    </message>
    <message>
        <source>Part in order</source>
        <translation>Деталь по порядку</translation>
    </message>
    <message>
        <source>Index</source>
        <translation>Индекс</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Значение</translation>
    </message>
    <message>
        <source>95 % interval</source>
        <translation>95 % интервал</translation>
    </message>
    <message numerus="yes">
        <source>Controller changes (marked): %n</source>
        <translation>
            <numerusform>Смены регулятора (отмечены): %n</numerusform>
            <numerusform>Смены регулятора (отмечены): %n</numerusform>
            <numerusform>Смены регулятора (отмечены): %n</numerusform>
        </translation>
    </message>
    <message>
        <source>The controller changes of these runs could not be read: %1</source>
        <translation>Смены регулятора этих серий не прочитаны: %1</translation>
    </message>
</context>
<context>
    <name>tt::ui::ReportsPage</name>
    <message>
        <source>Analyse</source>
        <translation>Анализ</translation>
    </message>
    <message>
        <source>PDF…</source>
        <translation>PDF…</translation>
    </message>
    <message>
        <source>CSV…</source>
        <translation>CSV…</translation>
    </message>
    <message>
        <source>DFQ…</source>
        <translation>DFQ…</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Отмена</translation>
    </message>
    <message>
        <source>No report</source>
        <translation>Нет отчёта</translation>
    </message>
    <message>
        <source>No measured parts for this choice</source>
        <translation>Для этого выбора нет измеренных деталей</translation>
    </message>
    <message>
        <source>Every part measured on the Run page is stored with its diameters and verdicts. Choose the machine, run and dates, then Analyse: control charts, capability and exports.</source>
        <translation>Каждая деталь, измеренная на странице «Работа», записывается с диаметрами и заключениями. Выберите станок, серию и даты, затем «Анализ»: контрольные карты, воспроизводимость и экспорт.</translation>
    </message>
    <message>
        <source>Reading the history…</source>
        <translation>Чтение истории…</translation>
    </message>
    <message>
        <source>Cancelled.</source>
        <translation>Отменено.</translation>
    </message>
    <message>
        <source>Written: %1</source>
        <translation>Записано: %1</translation>
    </message>
    <message>
        <source>No measured parts for this choice.</source>
        <translation>Для этого выбора нет измеренных деталей.</translation>
    </message>
    <message numerus="yes">
        <source>%n readings</source>
        <translation>
            <numerusform>%n измерение</numerusform>
            <numerusform>%n измерения</numerusform>
            <numerusform>%n измерений</numerusform>
        </translation>
    </message>
    <message>
        <source>Save the PDF report</source>
        <translation>Сохранить отчёт PDF</translation>
    </message>
    <message>
        <source>Save the readings as CSV</source>
        <translation>Сохранить измерения в CSV</translation>
    </message>
    <message>
        <source>Save the readings as DFQ</source>
        <translation>Сохранить измерения в DFQ</translation>
    </message>
    <message>
        <source>PDF files (*.pdf)</source>
        <translation>Файлы PDF (*.pdf)</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>Файлы CSV (*.csv)</translation>
    </message>
    <message>
        <source>AQDEF files (*.dfq)</source>
        <translation>Файлы AQDEF (*.dfq)</translation>
    </message>
    <message>
        <source>Writing the PDF…</source>
        <translation>Запись PDF…</translation>
    </message>
    <message>
        <source>Writing the DFQ file…</source>
        <translation>Запись файла DFQ…</translation>
    </message>
    <message>
        <source>Writing the CSV file…</source>
        <translation>Запись файла CSV…</translation>
    </message>
</context>
<context>
    <name>tt::ui::RunPage</name>
    <message>
        <source>Shaft profile (run-to-run)</source>
        <translation>Профиль вала (от детали к детали)</translation>
    </message>
    <message>
        <source>Boring bar (in-process)</source>
        <translation>Расточная оправка (в процессе)</translation>
    </message>
</context>
<context>
    <name>tt::ui::SettingsForm</name>
    <message>
        <source>%1 to %2</source>
        <translation>от %1 до %2</translation>
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
    <message>
        <source>Users and audit</source>
        <translation>Пользователи и аудит</translation>
    </message>
    <message>
        <source>Logged in</source>
        <translation>Вошёл</translation>
    </message>
    <message>
        <source>Log out</source>
        <translation>Выйти из системы</translation>
    </message>
    <message>
        <source>Users…</source>
        <translation>Пользователи…</translation>
    </message>
    <message>
        <source>Audit trail…</source>
        <translation>Журнал аудита…</translation>
    </message>
    <message>
        <source>This lathe in the plant database</source>
        <translation>Этот станок в заводской базе данных</translation>
    </message>
</context>
<context>
    <name>tt::ui::ShaftRunPanel</name>
    <message>
        <source>Pause on scrap</source>
        <translation>Пауза при браке</translation>
    </message>
    <message>
        <source>ready</source>
        <translation>готов</translation>
    </message>
    <message>
        <source>connecting</source>
        <translation>подключается</translation>
    </message>
    <message>
        <source>not answering</source>
        <translation>не отвечает</translation>
    </message>
    <message>
        <source>error</source>
        <translation>ошибка</translation>
    </message>
    <message>
        <source>the Run page was closed</source>
        <translation>страница «Работа» закрыта</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Пуск</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Стоп</translation>
    </message>
    <message>
        <source>Set-up</source>
        <translation>Наладка</translation>
    </message>
    <message>
        <source>Controller</source>
        <translation>Регулятор</translation>
    </message>
    <message>
        <source>Delay z, parts</source>
        <translation>Задержка z, дет.</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Скорость</translation>
    </message>
    <message>
        <source>LQG</source>
        <translation>ЛКГ</translation>
    </message>
    <message>
        <source>EWMA</source>
        <translation>EWMA</translation>
    </message>
    <message>
        <source>Open loop</source>
        <translation>Без регулятора</translation>
    </message>
    <message>
        <source>×1 (6 min a part)</source>
        <translation>×1 (6 мин/дет.)</translation>
    </message>
    <message>
        <source>×60 (6 s a part)</source>
        <translation>×60 (6 с/дет.)</translation>
    </message>
    <message>
        <source>×360 (1 s a part)</source>
        <translation>×360 (1 с/дет.)</translation>
    </message>
    <message>
        <source>×3600 (fastest)</source>
        <translation>×3600 (макс.)</translation>
    </message>
    <message>
        <source>Machine</source>
        <translation>Станок</translation>
    </message>
    <message>
        <source>CNC output</source>
        <translation>Выход в ЧПУ</translation>
    </message>
    <message>
        <source>Diameters from</source>
        <translation>Источник диаметров</translation>
    </message>
    <message>
        <source>Typed in by hand</source>
        <translation>Ручной ввод</translation>
    </message>
    <message>
        <source>Diameters by hand</source>
        <translation>Диаметры вручную</translation>
    </message>
    <message>
        <source>Part not measured</source>
        <translation>Деталь не измерена</translation>
    </message>
    <message>
        <source>Alarms</source>
        <translation>Тревоги</translation>
    </message>
    <message>
        <source>%1 — %2</source>
        <translation>%1 — %2</translation>
    </message>
    <message>
        <source>Not started: %1</source>
        <translation>Не запущено: %1</translation>
    </message>
    <message>
        <source>The run cannot start</source>
        <translation>Серию невозможно запустить</translation>
    </message>
    <message>
        <source>Run started: %1, %2, z = %3, %4</source>
        <translation>Серия запущена: %1, %2, z = %3, %4</translation>
    </message>
    <message>
        <source>the run did not start</source>
        <translation>серия не запустилась</translation>
    </message>
    <message>
        <source>the run is over</source>
        <translation>серия завершена</translation>
    </message>
    <message>
        <source>Continue</source>
        <translation>Продолжить</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Пауза</translation>
    </message>
    <message>
        <source>Stopped</source>
        <translation>Остановлено</translation>
    </message>
    <message>
        <source>Ready to start</source>
        <translation>Готов к пуску</translation>
    </message>
    <message>
        <source>Running</source>
        <translation>Выполняется</translation>
    </message>
    <message>
        <source>Paused — the CNC keeps the last correction</source>
        <translation>Пауза — ЧПУ сохраняет последнюю коррекцию</translation>
    </message>
    <message>
        <source>Fault — the CNC keeps the last correction</source>
        <translation>Авария — ЧПУ сохраняет последнюю коррекцию</translation>
    </message>
    <message>
        <source>%1: “%2” — %3</source>
        <translation>%1: «%2» — %3</translation>
    </message>
    <message>
        <source>CNC</source>
        <translation>ЧПУ</translation>
    </message>
    <message>
        <source>CNC: none (add a correction output on the Devices page)</source>
        <translation>ЧПУ: нет (добавьте выход коррекции на странице «Устройства»)</translation>
    </message>
    <message>
        <source>Gauge</source>
        <translation>Микрометр</translation>
    </message>
    <message>
        <source>Diameters: typed in by hand</source>
        <translation>Диаметры: ручной ввод</translation>
    </message>
    <message>
        <source>Parts done: %1</source>
        <translation>Готово деталей: %1</translation>
    </message>
    <message>
        <source>Machine: %1 (its own CNC, gauge and part cycle)</source>
        <translation>Станок: %1 (свои ЧПУ, измерительный прибор и цикл детали)</translation>
    </message>
    <message>
        <source>Press Start: %1</source>
        <translation>Нажмите «Пуск»: %1</translation>
    </message>
    <message>
        <source>Gauge: %1</source>
        <translation>Микрометр: %1</translation>
    </message>
    <message>
        <source>%1 · CNC: %2</source>
        <translation>%1 · ЧПУ: %2</translation>
    </message>
    <message>
        <source>The new controller tuning took over at part %1.</source>
        <translation>Новая настройка регулятора действует с детали %1.</translation>
    </message>
    <message>
        <source>A run is already going; stop it first.</source>
        <translation>Серия уже выполняется; сначала остановите её.</translation>
    </message>
    <message>
        <source>Continuing run %1 from part %2.</source>
        <translation>Серия %1 продолжается с детали %2.</translation>
    </message>
    <message>
        <source>The machine “%1” is not offered; choose another.</source>
        <translation>Станок «%1» не предлагается; выберите другой.</translation>
    </message>
    <message>
        <source>Choose a machine.</source>
        <translation>Выберите станок.</translation>
    </message>
</context>
<context>
    <name>tt::ui::ToolAuditModel</name>
    <message>
        <source>When</source>
        <translation>Когда</translation>
    </message>
    <message>
        <source>Who</source>
        <translation>Кто</translation>
    </message>
    <message>
        <source>Tool or material</source>
        <translation>Инструмент или материал</translation>
    </message>
    <message>
        <source>Field</source>
        <translation>Поле</translation>
    </message>
    <message>
        <source>Old</source>
        <translation>Было</translation>
    </message>
    <message>
        <source>New</source>
        <translation>Стало</translation>
    </message>
</context>
<context>
    <name>tt::ui::ToolImportModel</name>
    <message>
        <source>Take from file</source>
        <translation>Взять из файла</translation>
    </message>
    <message>
        <source>Keep table</source>
        <translation>Оставить таблицу</translation>
    </message>
    <message>
        <source>Line</source>
        <translation>Строка</translation>
    </message>
    <message>
        <source>Tool</source>
        <translation>Инструмент</translation>
    </message>
    <message>
        <source>In the table</source>
        <translation>В таблице</translation>
    </message>
    <message>
        <source>Differences (table → file) or problems</source>
        <translation>Различия (таблица → файл) или ошибки</translation>
    </message>
    <message>
        <source>Import</source>
        <translation>Импорт</translation>
    </message>
    <message>
        <source>new</source>
        <translation>новый</translation>
    </message>
    <message>
        <source>same</source>
        <translation>совпадает</translation>
    </message>
    <message>
        <source>different</source>
        <translation>отличается</translation>
    </message>
    <message>
        <source>cannot be read</source>
        <translation>не читается</translation>
    </message>
    <message>
        <source>Add</source>
        <translation>Добавить</translation>
    </message>
    <message>
        <source>Nothing to do</source>
        <translation>Без изменений</translation>
    </message>
    <message>
        <source>Skipped</source>
        <translation>Пропущен</translation>
    </message>
</context>
<context>
    <name>tt::ui::ToolTableModel</name>
    <message>
        <source>Tool</source>
        <translation>Инструмент</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Название</translation>
    </message>
    <message>
        <source>Section</source>
        <translation>Сечение</translation>
    </message>
    <message>
        <source>d, mm</source>
        <translation>d, мм</translation>
    </message>
    <message>
        <source>b, mm</source>
        <translation>b, мм</translation>
    </message>
    <message>
        <source>h, mm</source>
        <translation>h, мм</translation>
    </message>
    <message>
        <source>Overhang l, mm</source>
        <translation>Вылет l, мм</translation>
    </message>
    <message>
        <source>Material</source>
        <translation>Материал</translation>
    </message>
    <message>
        <source>E, MPa</source>
        <translation>E, МПа</translation>
    </message>
    <message>
        <source>Measured k, N/mm</source>
        <translation>Измеренная k, Н/мм</translation>
    </message>
    <message>
        <source>Measured on</source>
        <translation>Дата измерения</translation>
    </message>
    <message>
        <source>Measured by</source>
        <translation>Кем измерено</translation>
    </message>
    <message>
        <source>k_p, N/A</source>
        <translation>k_p, Н/А</translation>
    </message>
    <message>
        <source>k = 3EI/l³, N/mm</source>
        <translation>k = 3EI/l³, Н/мм</translation>
    </message>
    <message>
        <source>l/d</source>
        <translation>l/d</translation>
    </message>
    <message>
        <source>Computed from the section, the overhang and E; a measured stiffness overrides it</source>
        <translation>Рассчитывается по сечению, вылету и E; измеренная жёсткость имеет приоритет</translation>
    </message>
    <message>
        <source>round</source>
        <translation>круглое</translation>
    </message>
    <message>
        <source>rectangular</source>
        <translation>прямоугольное</translation>
    </message>
    <message>
        <source>Removed when you apply the changes</source>
        <translation>Будет удалён при применении изменений</translation>
    </message>
    <message>
        <source>Applied value: %1</source>
        <translation>Применённое значение: %1</translation>
    </message>
    <message>
        <source>%1 of %2</source>
        <translation>%2: %1</translation>
    </message>
    <message>
        <source>Add %1</source>
        <translation>Добавить %1</translation>
    </message>
    <message>
        <source>Remove %1</source>
        <translation>Удалить %1</translation>
    </message>
    <message>
        <source>Remove %1 tools</source>
        <translation>Удалить инструменты (%1)</translation>
    </message>
    <message>
        <source>id: %1 is also used in row %2</source>
        <translation>id: %1 уже используется в строке %2</translation>
    </message>
</context>
<context>
    <name>tt::ui::ToolsPage</name>
    <message>
        <source>Not accepted: %1</source>
        <translation>Не принято: %1</translation>
    </message>
    <message>
        <source>round</source>
        <translation>круглое</translation>
    </message>
    <message>
        <source>rectangular</source>
        <translation>прямоугольное</translation>
    </message>
    <message>
        <source>%1 (E %2 MPa)</source>
        <translation>%1 (E %2 МПа)</translation>
    </message>
    <message>
        <source>Enter your name on the Settings page first: every applied change is recorded with it.</source>
        <translation>Сначала введите своё имя на странице «Настройки»: каждое применённое изменение записывается вместе с ним.</translation>
    </message>
    <message>
        <source>%1: no operator name (Settings)</source>
        <translation>%1: нет имени оператора («Настройки»)</translation>
    </message>
    <message>
        <source>Undo: %1</source>
        <translation>Отменить: %1</translation>
    </message>
    <message>
        <source>Redo: %1</source>
        <translation>Вернуть: %1</translation>
    </message>
    <message>
        <source>Fix before applying: %1</source>
        <translation>Исправьте перед применением: %1</translation>
    </message>
    <message>
        <source>Changed tools: %1 (highlighted). They are not stored until you apply them.</source>
        <translation>Изменено инструментов: %1 (выделены). Они не сохраняются, пока вы не примените изменения.</translation>
    </message>
    <message>
        <source>All changes are applied. Double-click a cell to edit it.</source>
        <translation>Все изменения применены. Дважды щёлкните ячейку, чтобы изменить её.</translation>
    </message>
    <message>
        <source>Select the tools to remove first.</source>
        <translation>Сначала выберите инструменты для удаления.</translation>
    </message>
    <message>
        <source>Nothing to apply.</source>
        <translation>Нечего применять.</translation>
    </message>
    <message>
        <source>Apply changes</source>
        <translation>Применение изменений</translation>
    </message>
    <message>
        <source>These rows need fixing first:
%1</source>
        <translation>Сначала исправьте эти строки:
%1</translation>
    </message>
    <message>
        <source>Applied. Audit entries written with your name: %1.</source>
        <translation>Применено. Записей в журнале изменений с вашим именем: %1.</translation>
    </message>
    <message>
        <source>Nothing was stored: %1
Your edits are still here.</source>
        <translation>Ничего не сохранено: %1
Ваши правки не потеряны.</translation>
    </message>
    <message>
        <source>Not stored: %1</source>
        <translation>Не сохранено: %1</translation>
    </message>
    <message>
        <source>Discard changes</source>
        <translation>Отменить изменения</translation>
    </message>
    <message>
        <source>Discard the pending changes of %1 tools? The stored table stays as it is.</source>
        <translation>Отменить несохранённые изменения инструментов (%1)? Сохранённая таблица останется как есть.</translation>
    </message>
    <message>
        <source>Pending changes discarded.</source>
        <translation>Несохранённые изменения отменены.</translation>
    </message>
    <message>
        <source>Import tools</source>
        <translation>Импорт инструментов</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>Файлы CSV (*.csv)</translation>
    </message>
    <message>
        <source>%1 cannot be imported: %2</source>
        <translation>Не удаётся импортировать %1: %2</translation>
    </message>
    <message>
        <source>Import %1</source>
        <translation>Импорт %1</translation>
    </message>
    <message>
        <source>Tools imported from %1: %2, highlighted until you apply them.</source>
        <translation>Импортировано инструментов из %1: %2; они выделены, пока вы не примените изменения.</translation>
    </message>
    <message>
        <source>Import cancelled; the table is unchanged.</source>
        <translation>Импорт отменён; таблица не изменилась.</translation>
    </message>
    <message>
        <source>Export tools</source>
        <translation>Экспорт инструментов</translation>
    </message>
    <message>
        <source>Cannot write %1: %2</source>
        <translation>Не удаётся записать %1: %2</translation>
    </message>
    <message>
        <source>Exported %1 tools to %2, including %3 change(s) not applied yet.</source>
        <translation>Экспортировано инструментов: %1 в %2, в том числе ещё не применённых изменений: %3.</translation>
    </message>
    <message>
        <source>Exported %1 tools to %2.</source>
        <translation>Экспортировано инструментов: %1 в %2.</translation>
    </message>
    <message>
        <source>Add material</source>
        <translation>Добавить материал</translation>
    </message>
    <message>
        <source>New material %1</source>
        <translation>Новый материал %1</translation>
    </message>
    <message>
        <source>Added %1 (E 210000 MPa): double-click to rename it and set E.</source>
        <translation>Добавлен %1 (E 210000 МПа): дважды щёлкните, чтобы переименовать его и задать E.</translation>
    </message>
    <message>
        <source>Select the material to remove first.</source>
        <translation>Сначала выберите материал для удаления.</translation>
    </message>
    <message>
        <source>Remove material</source>
        <translation>Удалить материал</translation>
    </message>
    <message>
        <source>Removed %1; tools keep their stored E.</source>
        <translation>Удалён %1; у инструментов остаётся записанное E.</translation>
    </message>
    <message>
        <source>Edit material</source>
        <translation>Изменение материала</translation>
    </message>
    <message>
        <source>%1: E %2 MPa stored; tools keep the E they have until you choose the material again.</source>
        <translation>%1: сохранено E %2 МПа; у инструментов остаётся прежнее E, пока вы снова не выберете этот материал.</translation>
    </message>
    <message>
        <source>Add tool</source>
        <translation>Добавить</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Удалить</translation>
    </message>
    <message>
        <source>Undo</source>
        <translation>Отменить</translation>
    </message>
    <message>
        <source>Redo</source>
        <translation>Вернуть</translation>
    </message>
    <message>
        <source>Import CSV…</source>
        <translation>Импорт…</translation>
    </message>
    <message>
        <source>Export CSV…</source>
        <translation>Экспорт…</translation>
    </message>
    <message>
        <source>Discard</source>
        <translation>Сбросить</translation>
    </message>
    <message>
        <source>Young&apos;s modulus of each holder material. Choosing a material for a tool copies its E; every change here is stored at once and recorded in the audit.</source>
        <translation>Модуль Юнга каждого материала державки. При выборе материала для инструмента копируется его E; каждое изменение здесь сразу сохраняется и записывается в журнал изменений.</translation>
    </message>
    <message>
        <source>Tools</source>
        <translation>Инструменты</translation>
    </message>
    <message>
        <source>Materials</source>
        <translation>Материалы</translation>
    </message>
    <message>
        <source>Audit</source>
        <translation>Журнал изменений</translation>
    </message>
    <message>
        <source>Take all from file</source>
        <translation>Всё взять из файла</translation>
    </message>
    <message>
        <source>Keep all in table</source>
        <translation>Всё оставить в таблице</translation>
    </message>
    <message>
        <source>Import</source>
        <translation>Импортировать</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Отмена</translation>
    </message>
    <message>
        <source>%1 new, %2 different from the table, %3 the same, %4 cannot be read. Choose for each different tool whether to keep the table&apos;s values or take the file&apos;s; imported rows stay pending until you apply them.</source>
        <translation>Новых: %1, отличающихся от таблицы: %2, совпадающих: %3, нечитаемых: %4. Для каждого отличающегося инструмента выберите, оставить значения таблицы или взять из файла; импортированные строки не сохраняются, пока вы не примените изменения.</translation>
    </message>
    <message>
        <source>The tool table cannot be opened</source>
        <translation>Не удаётся открыть таблицу инструментов</translation>
    </message>
    <message>
        <source>%1&lt;br&gt;&lt;br&gt;The table is stored in the run history database; check the database on the Settings page.</source>
        <translation>%1&lt;br&gt;&lt;br&gt;Таблица хранится в базе данных истории серий; проверьте базу данных на странице «Настройки».</translation>
    </message>
    <message>
        <source>Apply changes</source>
        <comment>button</comment>
        <translation>Применить</translation>
    </message>
    <message numerus="yes">
        <source>%n changed tool(s) on the Tools page</source>
        <translation>
            <numerusform>%n изменённый инструмент на странице «Инструменты»</numerusform>
            <numerusform>%n изменённых инструмента на странице «Инструменты»</numerusform>
            <numerusform>%n изменённых инструментов на странице «Инструменты»</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>tt::ui::UserSession</name>
    <message>
        <source>Operator</source>
        <translation>Оператор</translation>
    </message>
    <message>
        <source>Engineer</source>
        <translation>Инженер</translation>
    </message>
    <message>
        <source>Quality</source>
        <translation>ОТК</translation>
    </message>
    <message>
        <source>Administrator</source>
        <translation>Администратор</translation>
    </message>
    <message>
        <source>nobody is logged in</source>
        <translation>никто не вошёл</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
</context>
<context>
    <name>tt::ui::UsersDialog</name>
    <message>
        <source>Users</source>
        <translation>Пользователи</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Имя</translation>
    </message>
    <message>
        <source>Role</source>
        <translation>Роль</translation>
    </message>
    <message>
        <source>Logs in with</source>
        <translation>Способ входа</translation>
    </message>
    <message>
        <source>State</source>
        <translation>Состояние</translation>
    </message>
    <message>
        <source>PIN (digits)</source>
        <translation>PIN (цифры)</translation>
    </message>
    <message>
        <source>Password</source>
        <translation>Пароль</translation>
    </message>
    <message>
        <source> failed log-ins</source>
        <translation> неудачных входов</translation>
    </message>
    <message>
        <source> min</source>
        <translation> мин</translation>
    </message>
    <message>
        <source>PIN or password</source>
        <translation>PIN или пароль</translation>
    </message>
    <message>
        <source>Add user</source>
        <translation>Добавить</translation>
    </message>
    <message>
        <source>Set role</source>
        <translation>Назначить роль</translation>
    </message>
    <message>
        <source>Set PIN or password</source>
        <translation>Задать PIN или пароль</translation>
    </message>
    <message>
        <source>Unlock</source>
        <translation>Разблокировать</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Удалить</translation>
    </message>
    <message>
        <source>Log-in rules</source>
        <translation>Правила входа</translation>
    </message>
    <message>
        <source>Lock out after</source>
        <translation>Блокировать после</translation>
    </message>
    <message>
        <source>Lock-out lasts</source>
        <translation>Блокировка длится</translation>
    </message>
    <message>
        <source>Log out when idle for</source>
        <translation>Выход при бездействии</translation>
    </message>
    <message>
        <source>Apply the rules</source>
        <translation>Применить правила</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>Закрыть</translation>
    </message>
    <message>
        <source>locked until %1</source>
        <translation>заблокирован до %1</translation>
    </message>
    <message>
        <source>active</source>
        <translation>активен</translation>
    </message>
    <message>
        <source>PIN</source>
        <translation>PIN</translation>
    </message>
    <message>
        <source>Not changed: %1</source>
        <translation>Не изменено: %1</translation>
    </message>
    <message>
        <source>%1 added.</source>
        <translation>%1 добавлен.</translation>
    </message>
    <message>
        <source>%1 is now %2.</source>
        <translation>%1 теперь: %2.</translation>
    </message>
    <message>
        <source>select a user first</source>
        <translation>сначала выберите пользователя</translation>
    </message>
    <message>
        <source>New PIN or password of %1 stored.</source>
        <translation>Новый PIN или пароль пользователя %1 сохранён.</translation>
    </message>
    <message>
        <source>%1 unlocked.</source>
        <translation>%1 разблокирован.</translation>
    </message>
    <message>
        <source>%1 removed.</source>
        <translation>%1 удалён.</translation>
    </message>
    <message>
        <source>Log-in rules stored.</source>
        <translation>Правила входа сохранены.</translation>
    </message>
</context>
<context>
    <name>tt::ui::VerdictCounter</name>
    <message>
        <source>Good: %1</source>
        <translation>Годных: %1</translation>
    </message>
    <message>
        <source>Rework: %1</source>
        <translation>Доработка: %1</translation>
    </message>
    <message>
        <source>Scrap: %1</source>
        <translation>Брак: %1</translation>
    </message>
    <message>
        <source>Yield: no part yet</source>
        <translation>Выход годных: деталей ещё нет</translation>
    </message>
    <message numerus="yes">
        <source>Yield: %1 % of %n part(s)</source>
        <translation>
            <numerusform>Выход годных: %1 % из %n детали</numerusform>
            <numerusform>Выход годных: %1 % из %n деталей</numerusform>
            <numerusform>Выход годных: %1 % из %n деталей</numerusform>
        </translation>
    </message>
    <message>
        <source>No part measured yet</source>
        <translation>Деталь ещё не измерена</translation>
    </message>
    <message>
        <source>Part %1: GOOD</source>
        <translation>Деталь %1: ГОДНАЯ</translation>
    </message>
    <message>
        <source>Part %1: REWORK</source>
        <translation>Деталь %1: ДОРАБОТКА</translation>
    </message>
    <message>
        <source>Part %1: SCRAP</source>
        <translation>Деталь %1: БРАК</translation>
    </message>
</context>
</TS>
