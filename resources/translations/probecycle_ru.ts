<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="ru_RU">
<context>
    <name>Calibration</name>
    <message>
        <source>%1 is not allowed: the spindle orientation is 0 or 180</source>
        <translation>%1 не допускается: ориентация шпинделя — 0 или 180</translation>
    </message>
    <message>
        <source>no points; a ring needs 3 or more per orientation</source>
        <translation>нет точек; для кольца нужно 3 или более точек на каждую ориентацию</translation>
    </message>
    <message>
        <source>orientation %1 has only %2 point (%3); a circle needs 3 or more per orientation (typically 4: X+, X-, Y+, Y-)</source>
        <translation>для ориентации %1 только %2 точка (%3); для окружности нужно 3 или более точек на ориентацию (обычно 4: X+, X-, Y+, Y-)</translation>
    </message>
    <message>
        <source>orientation %1 has only %2 points (%3); a circle needs 3 or more per orientation (typically 4: X+, X-, Y+, Y-)</source>
        <translation>для ориентации %1 только %2 точки (%3); для окружности нужно 3 или более точек на ориентацию (обычно 4: X+, X-, Y+, Y-)</translation>
    </message>
    <message>
        <source>the points at orientation %1 (%2) lie on a line or repeat: no circle through them; touch 3 or more distinct points around the bore</source>
        <translation>точки при ориентации %1 (%2) лежат на одной прямой или повторяются: окружность через них не проходит; коснитесь 3 или более разных точек по окружности отверстия</translation>
    </message>
    <message>
        <source>the points at %1 cover only %2 of the bore (all on one side): the centre across that side is poorly determined; touch around the whole bore (X+, X-, Y+, Y-)</source>
        <translation>точки при %1 охватывают только %2 отверстия (все с одной стороны): центр в направлении этой стороны определён плохо; касайтесь по всему отверстию (X+, X-, Y+, Y-)</translation>
    </message>
    <message>
        <source>3 points at %1: the circle passes through them exactly, so the residual shows nothing; a fourth point checks the touches</source>
        <translation>3 точки при %1: окружность проходит через них точно, поэтому остаток ничего не показывает; четвёртая точка проверяет касания</translation>
    </message>
    <message>
        <source>stylus runout %1 (x %2, y %3) exceeds %4: set the stylus on centre, and check that the spindle orients repeatably</source>
        <translation>биение наконечника %1 (x %2, y %3) превышает %4: выставьте наконечник по центру и проверьте повторяемость ориентации шпинделя</translation>
    </message>
    <message>
        <source>only orientation %1 given: no runout. The centre is that of the %1 circle and is off the gauge centre by the stylus runout; touch the same points at %2 to separate the two</source>
        <translation>задана только ориентация %1: биения нет. Центр — это центр окружности при %1, он смещён от центра кольца на биение наконечника; коснитесь тех же точек при %2, чтобы разделить их</translation>
    </message>
    <message>
        <source>a point is %1 off the fitted circle (limit %2): clean the gauge and the stylus, check the gauge is clamped, and repeat the touch</source>
        <translation>одна точка отстоит от подобранной окружности на %1 (предел %2): очистите кольцо и наконечник, проверьте закрепление кольца и повторите касание</translation>
    </message>
    <message>
        <source>the point on line %1 is %2 off the fitted circle (limit %3): clean the gauge and the stylus, check the gauge is clamped, and repeat the touch</source>
        <translation>точка в строке %1 отстоит от подобранной окружности на %2 (предел %3): очистите кольцо и наконечник, проверьте закрепление кольца и повторите касание</translation>
    </message>
    <message>
        <source>the touches lie on a circle of radius %1, not inside the gauge of radius %2 (diameter %3): the effective ball radius would not be positive; check the gauge diameter</source>
        <translation>касания лежат на окружности радиусом %1, а не внутри кольца радиусом %2 (диаметр %3): эффективный радиус шарика был бы неположительным; проверьте диаметр кольца</translation>
    </message>
    <message>
        <source>no trigger Z given; touch the surface at least once</source>
        <translation>Z срабатывания не задана; коснитесь поверхности хотя бы один раз</translation>
    </message>
    <message>
        <source>effective length %1 is not positive: with Z up, the trigger Z plus the active length offset must lie above the surface Z</source>
        <translation>эффективная длина %1 неположительна: при оси Z, направленной вверх, Z срабатывания плюс активная коррекция длины должна быть выше Z поверхности</translation>
    </message>
    <message>
        <source>the effective length differs from the nominal %1 by %2 (limit %3): check the nominal, the surface Z and the stylus</source>
        <translation>эффективная длина отличается от номинальной %1 на %2 (предел %3): проверьте номинал, Z поверхности и наконечник</translation>
    </message>
</context>
<context>
    <name>Comparison</name>
    <message>
        <source>a surface needs %1 points or more; got %2</source>
        <translation>для поверхности нужно точек не менее %1; получено: %2</translation>
    </message>
    <message>
        <source>the points lie on a line: they span no surface</source>
        <translation>точки лежат на одной прямой и не задают поверхность</translation>
    </message>
    <message>
        <source>the surface fit has no unique solution for these points</source>
        <translation>подбор поверхности по этим точкам не имеет единственного решения</translation>
    </message>
    <message>
        <source>face %1 at C = %2: the touches lie on a line and define no plane; touch the face at points spread over it</source>
        <translation>грань %1 при C = %2: касания лежат на одной прямой и не задают плоскость; касайтесь грани в точках, распределённых по всей её поверхности</translation>
    </message>
    <message>
        <source>block at C = %1: the three faces&apos; planes do not meet in one point (two of them are parallel); touch three faces of a corner</source>
        <translation>блок при C = %1: плоскости трёх граней не пересекаются в одной точке (две из них параллельны); касайтесь трёх граней, образующих угол</translation>
    </message>
    <message>
        <source>face %1 at C = %2: the touches nearly lie on a line (spread ratio %3); the face&apos;s tilt about that line is poorly known</source>
        <translation>грань %1 при C = %2: касания почти лежат на одной прямой (отношение разброса %3); наклон грани вокруг этой прямой определён плохо</translation>
    </message>
    <message>
        <source>face %1 at C = %2: a touch lies %3 off the face&apos;s plane (above %4); a chip, a burr or a bad touch?</source>
        <translation>грань %1 при C = %2: одна из точек касания отстоит от плоскости грани на %3 (больше %4); стружка, заусенец или плохое касание?</translation>
    </message>
    <message>
        <source>faces %1 and %2 at C = %3 meet at %4 (below %5): the corner is poorly defined</source>
        <translation>грани %1 и %2 при C = %3 сходятся под углом %4 (меньше %5): вершина угла определена плохо</translation>
    </message>
    <message>
        <source>a face has only 3 touches: its plane passes through them, so the C-axis errors&apos; uncertainty is unknown; touch each face 6 times</source>
        <translation>на одной из граней только 3 касания: плоскость проходит точно через них, поэтому неопределённость погрешностей оси C неизвестна; касайтесь каждой грани 6 раз</translation>
    </message>
    <message>
        <source>%1 measured points for %2 plan points; one measured point per plan point is needed</source>
        <translation>измеренных точек: %1, точек плана: %2; нужна одна измеренная точка на каждую точку плана</translation>
    </message>
    <message>
        <source>the block is needed at C = 0 and after the turn; only one is given</source>
        <translation>блок нужен при C = 0 и после поворота; задан только один из них</translation>
    </message>
    <message>
        <source>the surface through the %1 leaves residuals up to %2 (RMS %3, above %4): the plan may be too sparse for the part&apos;s form, or a point is wrong</source>
        <translation>поверхность через %1 оставляет остатки до %2 (СКЗ %3, больше %4): план может быть слишком редким для формы детали, или одна из точек ошибочна</translation>
    </message>
    <message>
        <source>reference&apos;s CMM points</source>
        <translation>точки КИМ эталонной детали</translation>
    </message>
    <message>
        <source>plan&apos;s nominal points</source>
        <translation>номинальные точки плана</translation>
    </message>
    <message>
        <source>calibrated reference points</source>
        <translation>калиброванные точки эталонной детали</translation>
    </message>
    <message>
        <source>%1 points project onto the edge of a fitted surface, not square onto it (points %2): their results are less sure</source>
        <translation>точек, проецирующихся на край подобранной поверхности, а не по нормали к ней: %1 (точки %2); их результаты менее надёжны</translation>
    </message>
    <message>
        <source>%1 measured points lie more than %2 from their plan points (points %3): are the files in the plan&apos;s order, and the C axis&apos;s position and angle right?</source>
        <translation>измеренных точек, удалённых от своих точек плана более чем на %2: %1 (точки %3); идут ли файлы в порядке плана и верны ли положение и угол оси C?</translation>
    </message>
    <message>
        <source>at %1 points the result differs from its first-order estimate by more than %2 (points %3): the surfaces do not follow the points there</source>
        <translation>точек, где результат отличается от оценки первого порядка более чем на %2: %1 (точки %3); там поверхности не следуют за точками</translation>
    </message>
    <message>
        <source>the C-axis errors&apos; uncertainty reaches %1 on the part (above %2): touch the block more often or on larger faces, or judge whether the correction helps</source>
        <translation>неопределённость погрешностей оси C достигает на детали %1 (больше %2): касайтесь блока чаще или на больших гранях либо оцените, помогает ли коррекция</translation>
    </message>
    <message>
        <source>only PTMEAS/CART,x,y,z,i,j,k is read; got &apos;%1&apos;</source>
        <translation>читается только PTMEAS/CART,x,y,z,i,j,k; получено «%1»</translation>
    </message>
    <message>
        <source>PTMEAS/CART has %1 numbers; the plan needs 6 (x, y, z, i, j, k)</source>
        <translation>чисел в PTMEAS/CART: %1; для плана нужно 6 (x, y, z, i, j, k)</translation>
    </message>
    <message>
        <source>PTMEAS/CART has %1 numbers; allowed: 3 (x, y, z) or 6 (x, y, z, i, j, k)</source>
        <translation>чисел в PTMEAS/CART: %1; допустимо: 3 (x, y, z) или 6 (x, y, z, i, j, k)</translation>
    </message>
    <message>
        <source>the normal (i, j, k) has length %1; allowed: a unit vector, length 1 within %2</source>
        <translation>длина нормали (i, j, k) равна %1; допустимо: единичный вектор, длина 1 с точностью до %2</translation>
    </message>
    <message>
        <source>point %1 has no plan point: the file has %2 points, the plan %3</source>
        <translation>для точки %1 нет точки плана: точек в файле: %2, в плане: %3</translation>
    </message>
    <message>
        <source>the file ends after %1 points; the plan has %2 (one measured point per plan point, in the plan&apos;s order)</source>
        <translation>файл заканчивается, точек в нём: %1; в плане: %2 (нужна одна измеренная точка на каждую точку плана, в порядке плана)</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a face; allowed: A, B, C</source>
        <translation>«%1» — не грань; допустимо: A, B, C</translation>
    </message>
    <message>
        <source>touches on face %1: %2; each face needs %3 or more (typically 6)</source>
        <translation>касаний на грани %1: %2; для каждой грани нужно не менее %3 (обычно 6)</translation>
    </message>
    <message>
        <source>no block touched: the C axis is taken as exact and its errors stay in the result; %1 from the axis, every 10 µrad of tilt or turn moves a point by %2</source>
        <translation>блок не измерялся: ось C считается точной, и её погрешности остаются в результате; на расстоянии %1 от оси каждые 10 мкрад наклона или поворота смещают точку на %2</translation>
    </message>
    <message>
        <source>a comparison needs %2 points or more; got %1</source>
        <translation>для сравнения нужно точек не менее %2; получено: %1</translation>
    </message>
    <message>
        <source>this point lies %1 from its plan point (plan line %2); allowed: within the plan&apos;s extent, %3; the points follow the plan&apos;s order, one per plan point</source>
        <translation>эта точка лежит в %1 от своей точки плана (строка плана %2); допустимо: в пределах размеров плана, %3; точки идут в порядке плана, по одной на точку плана</translation>
    </message>
    <message>
        <source>this point lies %1 from its plan point (plan line %2) but %3 from the plan point of line %4: the points must follow the plan&apos;s order, one per plan point</source>
        <translation>эта точка лежит в %1 от своей точки плана (строка плана %2), но в %3 от точки плана в строке %4: точки должны идти в порядке плана, по одной на точку плана</translation>
    </message>
</context>
<context>
    <name>CsvError</name>
    <message>
        <source>line %1: %2</source>
        <translation>строка %1: %2</translation>
    </message>
    <message>
        <source>line %1, column %2: %3</source>
        <translation>строка %1, столбец %2: %3</translation>
    </message>
    <message>
        <source>missing column &apos;%1&apos;; the header must name the columns %2 (comma-separated)</source>
        <translation>нет столбца «%1»; в заголовке должны быть столбцы %2 (через запятую)</translation>
    </message>
    <message>
        <source>column &apos;%1&apos; appears twice in the header</source>
        <translation>столбец «%1» встречается в заголовке дважды</translation>
    </message>
    <message>
        <source>%1 fields, but the header has %2 (%3)</source>
        <translation>полей: %1, а в заголовке: %2 (%3)</translation>
    </message>
    <message>
        <source>the file is empty; expected a header line %1 and one line per touch</source>
        <translation>файл пуст; ожидаются строка заголовка %1 и по строке на каждое касание</translation>
    </message>
    <message>
        <source>no data after the header; expected one line per touch under %1</source>
        <translation>после заголовка нет данных; ожидается по строке на каждое касание под %1</translation>
    </message>
    <message>
        <source>empty; expected a number</source>
        <translation>пусто; ожидается число</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a number (use &apos;.&apos; as the decimal point)</source>
        <translation>«%1» — не число (десятичный разделитель — точка «.»)</translation>
    </message>
    <message>
        <source>no line</source>
        <translation>нет строки</translation>
    </message>
    <message>
        <source>line %1</source>
        <translation>строка %1</translation>
    </message>
    <message>
        <source>lines %1</source>
        <translation>строки %1</translation>
    </message>
    <message>
        <source>out of range: a coordinate within +-%1 mm</source>
        <translation>вне диапазона: координата в пределах ±%1 мм</translation>
    </message>
</context>
<context>
    <name>DelayFit</name>
    <message>
        <source>%1, %2</source>
        <extracomment>a list of feeds, &quot;500 mm/min, 900 mm/min&quot;; %2 is the rest of the list</extracomment>
        <translation>%1, %2</translation>
    </message>
    <message>
        <source>%1: only %2 feeds; a line through two feeds cannot show whether the delay is constant: touch at 3 or more</source>
        <translation>%1: только %2 подачи; прямая по двум подачам не показывает, постоянна ли задержка: выполните касания на 3 или более подачах</translation>
    </message>
    <message>
        <source>%1: the fitted delay is negative (%2): the recorded position moves against the travel as the feed rises; check the direction column (+1/-1 is the direction of travel)</source>
        <translation>%1: подобранная задержка отрицательна (%2): с ростом подачи записанное положение смещается против направления движения; проверьте столбец direction (+1/-1 — направление движения)</translation>
    </message>
    <message>
        <source>%1: one touch only at %2: no scatter there; repeat each touch (5 or more) to see the stability</source>
        <translation>%1: только одно касание на подаче %2: разброса там не видно; повторите каждое касание (5 раз или более), чтобы увидеть стабильность</translation>
    </message>
    <message>
        <source>%1: at %2 the touches spread over %3 (%4 of travel), more than %5x what the other feeds predict (%6): the delay is not stable there; repeat the touches and check the input and the controller load</source>
        <translation>%1: на подаче %2 касания разбросаны на %3 (%4 движения), более чем в %5 раза больше, чем предсказывают другие подачи (%6): задержка там нестабильна; повторите касания и проверьте вход и загрузку ЧПУ</translation>
    </message>
    <message>
        <source>%1: the residuals curve: the touches depart from the line by up to %2; the delay is not constant but goes from %3 at %4 to %5 at %6; a correction with one delay is right at one feed only</source>
        <translation>%1: остатки искривлены: касания отклоняются от прямой до %2; задержка не постоянна, а меняется от %3 при %4 до %5 при %6; коррекция одной задержкой верна только на одной подаче</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not an axis name (a letter, e.g. X, Y, Z)</source>
        <translation>«%1» — не имя оси (буква, напр. X, Y, Z)</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not allowed: +1 or -1, the direction of travel</source>
        <translation>«%1» не допускается: +1 или -1, направление движения</translation>
    </message>
    <message>
        <source>%1 is out of range: (0, %2] mm/min</source>
        <translation>%1 вне диапазона: (0, %2] мм/мин</translation>
    </message>
    <message>
        <source>%1: only one touch (%2, %3); the delay is the slope over feeds: touch at 2 or more feeds, 3 or more to check that it is constant</source>
        <translation>%1: только одно касание (%2, %3); задержка — это наклон по подачам: выполните касания на 2 или более подачах, на 3 или более — чтобы проверить её постоянство</translation>
    </message>
    <message>
        <source>%1: all %2 touches are at one feed (%3, %4); the delay is the slope over feeds: touch at 2 or more feeds, 3 or more to check that it is constant</source>
        <translation>%1: все касания (%2) выполнены на одной подаче (%3, %4); задержка — это наклон по подачам: выполните касания на 2 или более подачах, на 3 или более — чтобы проверить её постоянство</translation>
    </message>
    <message>
        <source>the fit has no groups of touches</source>
        <translation>в подборе нет групп касаний</translation>
    </message>
    <message>
        <source>the group chosen</source>
        <translation>выбранная группа</translation>
    </message>
    <message>
        <source>got &apos;%1&apos;; allowed: a group of the file (%2)</source>
        <translation>получено «%1»; допустимо: группа из файла (%2)</translation>
    </message>
    <message>
        <source>the only group</source>
        <translation>единственная группа</translation>
    </message>
    <message>
        <source>the longest delay of %1 groups (the safe side for overtravel); choose one to override</source>
        <translation>наибольшая задержка из %1 групп (в безопасную сторону для перебега); выберите группу, чтобы заменить</translation>
    </message>
    <message>
        <source>the fitted delay of %1, %2, is shorter than the scenario&apos;s probe.interface_delay_s + half of machine.scan_period_s (%3): the controller latency would be negative; check those keys (or machine.latched_input) in the scenario</source>
        <translation>подобранная задержка %1, %2, меньше, чем probe.interface_delay_s плюс половина machine.scan_period_s в сценарии (%3): задержка ЧПУ была бы отрицательной; проверьте эти ключи (или machine.latched_input) в сценарии</translation>
    </message>
    <message>
        <source>the fitted delay of %1, %2, is negative: the input is latched, so it would be the probe&apos;s interface delay; check the touches</source>
        <translation>подобранная задержка %1, %2, отрицательна: вход с защёлкой, и она была бы задержкой интерфейса датчика; проверьте касания</translation>
    </message>
</context>
<context>
    <name>Feature</name>
    <message>
        <source>surface</source>
        <translation>плоскость</translation>
    </message>
    <message>
        <source>web</source>
        <translation>стенка</translation>
    </message>
    <message>
        <source>pocket</source>
        <translation>паз</translation>
    </message>
    <message>
        <source>bore</source>
        <translation>отверстие</translation>
    </message>
    <message>
        <source>boss</source>
        <translation>бобышка</translation>
    </message>
</context>
<context>
    <name>FieldError</name>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>%1: got %2; allowed: %3</source>
        <translation>%1: получено %2; допустимо: %3</translation>
    </message>
    <message>
        <source>a number from %1 to %2 %3</source>
        <translation>число от %1 до %2 %3</translation>
    </message>
    <message>
        <source>one of %1</source>
        <translation>одно из: %1</translation>
    </message>
    <message>
        <source>true or false</source>
        <translation>true или false</translation>
    </message>
    <message>
        <source>unknown key; allowed in %1: %2</source>
        <translation>неизвестный ключ; допустимые в %1: %2</translation>
    </message>
    <message>
        <source>more than twice cycle.approach_mm (%1) for a %2</source>
        <translation>больше удвоенного cycle.approach_mm (%1) для элемента «%2»</translation>
    </message>
    <message>
        <source>malformed JSON: %1</source>
        <translation>ошибка в JSON: %1</translation>
    </message>
    <message>
        <source>a number out of range: %1</source>
        <translation>число вне допустимого диапазона: %1</translation>
    </message>
    <message>
        <source>a JSON object with sections machine, probe, cycle</source>
        <translation>объект JSON с разделами machine, probe, cycle</translation>
    </message>
    <message>
        <source>an object of keys</source>
        <translation>объект с ключами</translation>
    </message>
    <message>
        <source>section.key=value</source>
        <translation>раздел.ключ=значение (section.key=value)</translation>
    </message>
    <message>
        <source>unknown key; sections are machine, probe, cycle</source>
        <translation>неизвестный ключ; разделы: machine, probe, cycle</translation>
    </message>
    <message>
        <source>a number in (%1, %2)</source>
        <translation>число в интервале (%1, %2)</translation>
    </message>
    <message>
        <source>a number in (%1, %2]</source>
        <translation>число в интервале (%1, %2]</translation>
    </message>
    <message>
        <source>a number in [%1, %2)</source>
        <translation>число в интервале [%1, %2)</translation>
    </message>
    <message>
        <source>a number in [%1, %2]</source>
        <translation>число в интервале [%1, %2]</translation>
    </message>
    <message>
        <source>+1 or -1</source>
        <translation>+1 или -1</translation>
    </message>
    <message>
        <source>a counter wide enough that one cycle (%1 counts) moves it by less than half its range</source>
        <translation>счётчик такой разрядности, чтобы за один период (%1 импульсов) он изменялся меньше чем на половину своего диапазона</translation>
    </message>
    <message>
        <source>text without NUL bytes; one is at line %1, column %2</source>
        <translation>текст без байтов NUL; такой байт в строке %1, столбце %2</translation>
    </message>
    <message>
        <source>at most %3 levels of nesting; line %1, column %2 opens one more</source>
        <translation>не более %3 уровней вложенности; строка %1, столбец %2 открывает ещё один</translation>
    </message>
    <message>
        <source>a key with a name; line %1, column %2 has an empty key &quot;&quot;</source>
        <translation>ключ с именем; в строке %1, столбце %2 пустой ключ &quot;&quot;</translation>
    </message>
    <message>
        <source>each key once per object; it is given at line %1 and again at line %2</source>
        <translation>каждый ключ один раз в объекте; он задан в строке %1 и ещё раз в строке %2</translation>
    </message>
    <message>
        <source>%1: got %2... (%4 characters); allowed: %3</source>
        <translation>%1: получено %2... (%4 символов); допустимо: %3</translation>
    </message>
    <message>
        <source>a number a double can hold (up to about 1.8e308); at line %1 it is out of range</source>
        <translation>число, представимое типом double (до примерно 1,8e308); в строке %1 оно вне диапазона</translation>
    </message>
    <message>
        <source>unknown section; allowed: %1</source>
        <translation>неизвестный раздел; допустимые: %1</translation>
    </message>
    <message>
        <source>a JSON object with the comparison&apos;s files and settings</source>
        <translation>объект JSON с файлами и настройками сравнения</translation>
    </message>
    <message>
        <source>&quot;probecycle-comparison&quot;</source>
        <translation>&quot;probecycle-comparison&quot;</translation>
    </message>
    <message>
        <source>1</source>
        <translation>1</translation>
    </message>
    <message>
        <source>a file path as text (empty: none)</source>
        <translation>путь к файлу в виде текста (пусто — нет файла)</translation>
    </message>
    <message>
        <source>an unknown key; allowed: %1</source>
        <translation>неизвестный ключ; допустимые: %1</translation>
    </message>
    <message>
        <source>a number from %1 to %2</source>
        <translation>число от %1 до %2</translation>
    </message>
    <message>
        <source>text</source>
        <translation>текст</translation>
    </message>
    <message>
        <source>a whole number from %1 to %2</source>
        <translation>целое число от %1 до %2</translation>
    </message>
    <message>
        <source>&quot;probecycle-project&quot; (a ProbeCycle project)</source>
        <translation>&quot;probecycle-project&quot; (проект ProbeCycle)</translation>
    </message>
    <message>
        <source>1 (a newer ProbeCycle wrote this file)</source>
        <translation>1 (файл записан более новой версией ProbeCycle)</translation>
    </message>
    <message>
        <source>missing; a project holds a scenario</source>
        <translation>отсутствует; проект содержит сценарий</translation>
    </message>
    <message>
        <source>from 2 to %1 different feeds</source>
        <translation>от 2 до %1 различных подач</translation>
    </message>
    <message>
        <source>one line of text, at most %1 characters</source>
        <translation>одна строка текста, не более %1 символов</translation>
    </message>
    <message>
        <source>true or false (true on a probe only)</source>
        <translation>true или false (true только для касания)</translation>
    </message>
    <message>
        <source>&quot;probecycle-probing-plan&quot; (a plan that probecycle-cli program wrote)</source>
        <translation>&quot;probecycle-probing-plan&quot; (план, записанный probecycle-cli program)</translation>
    </message>
    <message>
        <source>a list of at most 20000 steps</source>
        <translation>список не более чем из 20000 шагов</translation>
    </message>
    <message>
        <source>no recorded probe; a plan needs one or more</source>
        <translation>нет записываемых касаний; плану нужно одно или больше</translation>
    </message>
    <message>
        <source>X+, X-, Y+ or Y- for a %1 (touched from both sides along X or Y)</source>
        <translation>X+, X-, Y+ или Y- для элемента «%1» (касания с обеих сторон вдоль X или Y)</translation>
    </message>
    <message>
        <source>at least %1 for a %2 (the probe moves over its wall between touches)</source>
        <translation>не менее %1 для элемента «%2» (между касаниями датчик проходит над ним)</translation>
    </message>
    <message>
        <source>at most %1 for a %2&apos;s program (its moves from the centre to the touches&apos; starts are at most %3)</source>
        <translation>не более %1 для программы элемента «%2» (её перемещения от центра к началу касаний не длиннее %3)</translation>
    </message>
    <message>
        <source>at least %1, the stop of the touch at %2 past its surface (a search that ends sooner is braking when it touches), or 0 for automatic</source>
        <translation>не менее %1 — точки остановки касания на %2 за поверхностью (поиск, который заканчивается раньше, касается уже при торможении), или 0 — автоматически</translation>
    </message>
    <message>
        <source>a feed at which an obstruction met by a protected move stops short of the probe&apos;s %1 limit (now %2 past it)</source>
        <translation>подача, при которой защищённое перемещение, встретив препятствие, останавливается до предела датчика %1 (сейчас — в %2 за препятствием)</translation>
    </message>
    <message>
        <source>less than %1, the %2&apos;s distance between stylus centres (cycle.feature_size_mm)</source>
        <translation>меньше %1 — расстояния между центрами наконечника для элемента (%2) (cycle.feature_size_mm)</translation>
    </message>
    <message>
        <source>the whole number 1 (this ProbeCycle&apos;s project version)</source>
        <translation>целое число 1 (версия проекта этой ProbeCycle)</translation>
    </message>
</context>
<context>
    <name>FileError</name>
    <message>
        <source>cannot write %1: %2</source>
        <translation>не удаётся записать %1: %2</translation>
    </message>
    <message>
        <source>cannot open %1: %2</source>
        <translation>не удаётся открыть %1: %2</translation>
    </message>
    <message>
        <source>it is a directory</source>
        <translation>это папка</translation>
    </message>
    <message>
        <source>it is not a regular file (a pipe, a device or a socket); ProbeCycle writes only regular files</source>
        <translation>это не обычный файл (канал, устройство или сокет); ProbeCycle записывает только обычные файлы</translation>
    </message>
    <message>
        <source>it is a symbolic link to a folder that does not exist</source>
        <translation>это символическая ссылка на несуществующую папку</translation>
    </message>
    <message>
        <source>it has more than %1 bytes, the limit for an input file (%2 MiB)</source>
        <translation>в нём больше %1 байт — предела для входного файла (%2 МиБ)</translation>
    </message>
    <message>
        <source>it has %1 bytes; the limit for an input file is %2 bytes (%3 MiB)</source>
        <translation>в нём %1 байт; предел для входного файла — %2 байт (%3 МиБ)</translation>
    </message>
    <message>
        <source>it is read-only; ProbeCycle does not replace a protected file</source>
        <translation>он только для чтения; ProbeCycle не заменяет защищённый файл</translation>
    </message>
    <message>
        <source>the folder %1 cannot be written to (%2)</source>
        <translation>в папку %1 нельзя записывать (%2)</translation>
    </message>
    <message>
        <source>another output of this command goes there too (%1); give each output a file of its own</source>
        <translation>туда же пишется и другой результат этой команды (%1); дайте каждому результату свой файл</translation>
    </message>
    <message>
        <source>it is not a folder; give a folder that does not exist yet, or one this command wrote before</source>
        <translation>это не папка; укажите папку, которой ещё нет, или ту, что эта команда уже записала</translation>
    </message>
    <message>
        <source>its parent folder does not exist</source>
        <translation>её родительской папки не существует</translation>
    </message>
    <message>
        <source>the folder holds %1 entries other than the files this command writes (%2); give a new or empty folder</source>
        <translation>в папке есть другие записи, кроме файлов этой команды (%1: %2); укажите новую или пустую папку</translation>
    </message>
    <message>
        <source>its name is a Windows device&apos;s (CON, PRN, AUX, NUL, COM1-9, LPT1-9, with any extension); give another name</source>
        <translation>это имя устройства Windows (CON, PRN, AUX, NUL, COM1-9, LPT1-9, с любым расширением); дайте другое имя</translation>
    </message>
</context>
<context>
    <name>LinuxCncIni</name>
    <message>
        <source>a decimal number</source>
        <translation>десятичное число</translation>
    </message>
    <message>
        <source>missing section; expected %1 (for %2)</source>
        <translation>раздел отсутствует; ожидается %1 (для %2)</translation>
    </message>
    <message>
        <source>missing; expected %1 (for %2)</source>
        <translation>отсутствует; ожидается %1 (для %2)</translation>
    </message>
    <message>
        <source>no value; expected %1 (for %2)</source>
        <translation>нет значения; ожидается %1 (для %2)</translation>
    </message>
    <message>
        <source>got %1; allowed: %2 (for %3)</source>
        <translation>получено %1; допустимо: %2 (для %3)</translation>
    </message>
    <message>
        <source>line %1: %2</source>
        <translation>строка %1: %2</translation>
    </message>
    <message>
        <source>[%1]: %2</source>
        <translation>[%1]: %2</translation>
    </message>
    <message>
        <source>[%1] %2: %3</source>
        <translation>[%1] %2: %3</translation>
    </message>
    <message>
        <source>[%1] %2, line %3: %4</source>
        <translation>[%1] %2, строка %3: %4</translation>
    </message>
    <message>
        <source>#INCLUDE is not followed; LinuxCNC writes the configuration with its includes to NAME.ini.expanded beside the INI file when it starts: read that file</source>
        <translation>#INCLUDE не обрабатывается; при запуске LinuxCNC записывает конфигурацию с подключёнными файлами в NAME.ini.expanded рядом с INI-файлом: прочитайте этот файл</translation>
    </message>
    <message>
        <source>a whole number from %1 to %2 ns</source>
        <translation>целое число от %1 до %2 нс</translation>
    </message>
    <message>
        <source>one of %1, or a number of units per mm from %2 to %3</source>
        <translation>одно из: %1, или число единиц на мм от %2 до %3</translation>
    </message>
</context>
<context>
    <name>MachineLog</name>
    <message>
        <source>cannot read &apos;%1&apos;; expected %2</source>
        <translation>не удаётся прочитать «%1»; ожидалось %2</translation>
    </message>
    <message>
        <source>the log ends after %1 of the plan&apos;s %2 probe positions: the program stopped early, a position was not recorded, or the log is from another plan; nothing imported</source>
        <translation>журнал заканчивается после %1 из %2 положений касания плана: программа остановилась раньше, положение не записано или журнал от другого плана; ничего не импортировано</translation>
    </message>
    <message>
        <source>a probe position more than the plan&apos;s %1: the program ran twice into one log, or the log is from another plan; nothing imported</source>
        <translation>положений касания больше, чем %1 в плане: программа выполнена дважды в один журнал или журнал от другого плана; ничего не импортировано</translation>
    </message>
    <message>
        <source>%1 moved %2 since line %3, but the plan moves only %4 between these probes: is the log from another plan? Nothing imported</source>
        <translation>%1 переместилась на %2 после строки %3, а план перемещает только %4 между этими касаниями: журнал от другого плана? Ничего не импортировано</translation>
    </message>
    <message>
        <source>the log is from plan %1, the plan file is plan %2: give the plan the program was made from; nothing imported</source>
        <translation>журнал от плана %1, файл плана — план %2: укажите план, по которому создана программа; ничего не импортировано</translation>
    </message>
    <message>
        <source>touch %1 where touch %2 was due: the log holds more than one run; nothing imported</source>
        <translation>касание %1 там, где ожидалось касание %2: в журнале больше одного прогона; ничего не импортировано</translation>
    </message>
    <message>
        <source>grbl raised &apos;%1&apos; (ALARM:5: the probe did not touch; ALARM:4: it was triggered before the move): the program stopped there; nothing imported</source>
        <translation>grbl выдал «%1» (ALARM:5: датчик не коснулся; ALARM:4: датчик сработал до движения): программа остановилась там; ничего не импортировано</translation>
    </message>
    <message>
        <source>the probe did not trigger (%1); nothing imported</source>
        <translation>датчик не сработал (%1); ничего не импортировано</translation>
    </message>
    <message>
        <source>a cycle plan&apos;s positions have no table in the lab; import the log of a delay or a ring program</source>
        <translation>для положений плана цикла в лаборатории нет таблицы; импортируйте журнал программы задержки или кольца</translation>
    </message>
    <message>
        <source>the program printed PROBECYCLE NO TRIGGER: a probe did not trigger and the control stopped with alarm 101; nothing imported</source>
        <translation>программа вывела PROBECYCLE NO TRIGGER: датчик не сработал, и система ЧПУ остановилась с аварией 101; ничего не импортировано</translation>
    </message>
    <message>
        <source>a touch before the line PROBECYCLE PLAN that the program prints first: capture its output from the start; nothing imported</source>
        <translation>касание до строки PROBECYCLE PLAN, которую программа выводит первой: записывайте вывод с самого начала; ничего не импортировано</translation>
    </message>
    <message>
        <source>no line PROBECYCLE PLAN: is this the DPRNT output of a ProbeCycle program? Nothing imported</source>
        <translation>нет строки PROBECYCLE PLAN: это вывод DPRNT программы ProbeCycle? Ничего не импортировано</translation>
    </message>
    <message>
        <source>the probe touched something during a protected move (%1): its path is obstructed, and grbl, which cannot stop a program on it, went on; check the machine; nothing imported</source>
        <translation>датчик коснулся чего-то во время защищённого перемещения (%1): на пути препятствие, а grbl, который не может остановить на этом программу, продолжил её; проверьте станок; ничего не импортировано</translation>
    </message>
    <message>
        <source>the program printed PROBECYCLE OBSTRUCTED: the probe touched something during a protected move and the control stopped with alarm 102; nothing imported</source>
        <translation>программа вывела PROBECYCLE OBSTRUCTED: датчик коснулся чего-то во время защищённого перемещения, и система ЧПУ остановилась с аварией 102; ничего не импортировано</translation>
    </message>
    <message>
        <source>the program&apos;s result line gives %1 %2, its touches give %3: was the program edited, or written from another plan? Nothing imported</source>
        <translation>строка результата программы даёт %1 %2, её касания дают %3: программу изменяли или она создана по другому плану? Ничего не импортировано</translation>
    </message>
    <message>
        <source>a %1 plan has no feature result: its import is the lab&apos;s CSV</source>
        <translation>у плана %1 нет результата элемента: его импорт — это CSV лаборатории</translation>
    </message>
    <message>
        <source>the cycle plan has no readable value %1: write the program and its plan again with this version of ProbeCycle</source>
        <translation>в плане цикла нет читаемого значения %1: создайте программу и её план заново этой версией ProbeCycle</translation>
    </message>
    <message>
        <source>the cycle plan&apos;s recorded touches do not make the sides of its %1: was the plan file edited?</source>
        <translation>записанные касания плана цикла не образуют стороны элемента (%1): файл плана изменяли?</translation>
    </message>
    <message>
        <source>this line is from a %1 log, and no line is from a %2 log: import it as %1 (--dialect %1); nothing imported</source>
        <translation>эта строка из журнала %1, а строк журнала %2 нет: импортируйте его как %1 (--dialect %1); ничего не импортировано</translation>
    </message>
    <message>
        <source>the console does not open with the plan&apos;s signature (four [PRB:...:0] answers to the protected moves before the first probe): it is from another plan&apos;s or an older ProbeCycle&apos;s program (make the program again from this plan), or the probe touched something during those moves (give it free air); nothing imported</source>
        <translation>консоль не начинается с подписи плана (четыре ответа [PRB:...:0] на защищённые перемещения перед первым касанием): она от программы другого плана или более старой ProbeCycle (создайте программу заново по этому плану), либо датчик коснулся чего-то во время этих перемещений (дайте ему свободное пространство); ничего не импортировано</translation>
    </message>
    <message>
        <source>the console is from another plan (its signature reads %1, this plan&apos;s is %2): give the plan the program was made from; nothing imported</source>
        <translation>консоль от другого плана (её подпись — %1, подпись этого плана — %2): укажите план, по которому создана программа; ничего не импортировано</translation>
    </message>
    <message>
        <source>#%1 is listed again with another value (first on line %2): the list holds more than one output; nothing imported</source>
        <translation>#%1 указана снова с другим значением (впервые в строке %2): в списке больше одного вывода; ничего не импортировано</translation>
    </message>
    <message>
        <source>no value of #%1 in the list: list every common variable from #500 to #%2 that the program set; nothing imported</source>
        <translation>в списке нет значения #%1: перечислите все общие переменные от #500 до #%2, заданные программой; ничего не импортировано</translation>
    </message>
    <message>
        <source>no values of #500 to #503, where the program keeps its plan: is this the list of common variables after a ProbeCycle program? Nothing imported</source>
        <translation>нет значений #500–#503, где программа хранит свой план: это список общих переменных после программы ProbeCycle? Ничего не импортировано</translation>
    </message>
    <message>
        <source>#504 is 101: a probe did not trigger and the program stopped at PROBE DID NOT TRIGGER; nothing imported</source>
        <translation>#504 равна 101: щуп не сработал, и программа остановилась на PROBE DID NOT TRIGGER; ничего не импортировано</translation>
    </message>
    <message>
        <source>#504 is 102: the probe touched something during a protected move and the program stopped at PROBE PATH OBSTRUCTED; nothing imported</source>
        <translation>#504 равна 102: щуп коснулся чего-то при защищённом перемещении, и программа остановилась на PROBE PATH OBSTRUCTED; ничего не импортировано</translation>
    </message>
    <message>
        <source>#504 is %1: the program did not end (1 when it ends, 103 when it stops out of tolerance); nothing imported</source>
        <translation>#504 равна %1: программа не завершилась (1 — при завершении, 103 — при остановке из-за выхода за допуск); ничего не импортировано</translation>
    </message>
</context>
<context>
    <name>Optimise</name>
    <message>
        <source>no setting meets the requirements: the probe&apos;s maximum feed %1 is under the lowest feed, %2</source>
        <translation>ни одна настройка не удовлетворяет требованиям: максимальная подача щупа %1 ниже наименьшей подачи %2</translation>
    </message>
    <message>
        <source>no setting meets the requirements: the overtravel must stay at or under %1 of the probe&apos;s limit %2 (probe.overtravel_limit_mm), and even at %3 it is %4</source>
        <translation>ни одна настройка не удовлетворяет требованиям: перебег должен быть не больше %1 от предела щупа %2 (probe.overtravel_limit_mm), а даже при %3 он составляет %4</translation>
    </message>
    <message>
        <source>no setting meets the requirements: a start distance of the part position uncertainty %1 plus the room to reach even %2 (%3) does not fit a %4 of %5</source>
        <translation>ни одна настройка не удовлетворяет требованиям: расстояние подхода из неопределённости положения детали %1 и пути разгона даже до %2 (%3) не помещается в элемент «%4» размером %5</translation>
    </message>
    <message>
        <source>no setting meets every requirement</source>
        <translation>ни одна настройка не удовлетворяет всем требованиям</translation>
    </message>
    <message>
        <source>the overtravel fraction %1 is out of range: allowed from %2 to %3</source>
        <translation>доля перебега %1 вне диапазона: допустимо от %2 до %3</translation>
    </message>
    <message>
        <source>the skip input&apos;s scan period %1 limits the measuring feed; a latched input would save %2 a cycle</source>
        <translation>период опроса входа пропуска %1 ограничивает измерительную подачу; вход с защёлкой сэкономил бы %2 за цикл</translation>
    </message>
    <message>
        <source>the probe&apos;s maximum feed %1 limits the cycle; a probe rated for faster feeds would save %2 a cycle</source>
        <translation>максимальная подача щупа %1 ограничивает цикл; щуп, рассчитанный на бо́льшие подачи, сэкономил бы %2 за цикл</translation>
    </message>
    <message>
        <source>no setting meets the target uncertainty %1 (cycle.target_uncertainty_mm): the smallest achievable is %2, at %3 and cycle.repeats %4 (the probe&apos;s repeatability is %5; the budget&apos;s terms no feed changes, lobing, calibration artefact, machine repeatability and thermal drift, are %6 together)</source>
        <translation>ни одна настройка не обеспечивает целевую неопределённость %1 (cycle.target_uncertainty_mm): наименьшая достижимая — %2, при %3 и cycle.repeats %4 (повторяемость датчика %5; члены бюджета, не зависящие от подачи, — лепестковость, эталон калибровки, повторяемость станка и температурный дрейф — вместе дают %6)</translation>
    </message>
    <message>
        <source>no setting meets the current uncertainty %1: the smallest achievable is %2, at %3 and cycle.repeats %4 (the probe&apos;s repeatability is %5; the budget&apos;s terms no feed changes, lobing, calibration artefact, machine repeatability and thermal drift, are %6 together)</source>
        <translation>ни одна настройка не обеспечивает текущую неопределённость %1: наименьшая достижимая — %2, при %3 и cycle.repeats %4 (повторяемость датчика %5; члены бюджета, не зависящие от подачи, — лепестковость, эталон калибровки, повторяемость станка и температурный дрейф — вместе дают %6)</translation>
    </message>
</context>
<context>
    <name>Parameter</name>
    <message>
        <source>Time constant</source>
        <translation>Постоянная времени</translation>
    </message>
    <message>
        <source>Acceleration time constant T: the control reaches any programmed feed in T (a = v/T). Sets the distance to reach the feed (v*T/2) and the braking distance after the trigger, and so overtravel and cycle time. Used by the time-constant model.</source>
        <translation>Постоянная времени разгона T: система ЧПУ достигает любой запрограммированной подачи за время T (a = v/T). Определяет путь разгона до подачи (v*T/2) и тормозной путь после срабатывания, а значит перебег и время цикла. Используется моделью с постоянной времени.</translation>
    </message>
    <message>
        <source>ms</source>
        <translation>мс</translation>
    </message>
    <message>
        <source>Max. acceleration</source>
        <translation>Макс. ускорение</translation>
    </message>
    <message>
        <source>Maximum axis acceleration, used by the constant-acceleration and jerk-limited models for every move and for braking after the trigger.</source>
        <translation>Максимальное ускорение оси; модели с постоянным ускорением и с ограничением рывка применяют его ко всем перемещениям и к торможению после срабатывания.</translation>
    </message>
    <message>
        <source>mm/s²</source>
        <translation>мм/с²</translation>
    </message>
    <message>
        <source>Max. jerk</source>
        <translation>Макс. рывок</translation>
    </message>
    <message>
        <source>Maximum axis jerk, used by the jerk-limited (S-curve) model: lower jerk lengthens every acceleration and the braking after the trigger.</source>
        <translation>Максимальный рывок оси для модели с ограничением рывка (S-кривая): чем меньше рывок, тем дольше каждый разгон и торможение после срабатывания.</translation>
    </message>
    <message>
        <source>mm/s³</source>
        <translation>мм/с³</translation>
    </message>
    <message>
        <source>Rapid feed</source>
        <translation>Ускоренная подача</translation>
    </message>
    <message>
        <source>mm/min</source>
        <translation>мм/мин</translation>
    </message>
    <message>
        <source>Scan period</source>
        <translation>Период опроса</translation>
    </message>
    <message>
        <source>Machine response time</source>
        <translation>Время отклика станка</translation>
    </message>
    <message>
        <source>Fixed latency of the control after it has seen the input. Removed by calibration, but the axis keeps moving: adds trigger speed × latency to the overtravel.</source>
        <translation>Постоянная задержка ЧПУ после того, как вход замечен. Калибровка убирает её из измеренного значения, но ось продолжает двигаться: к перебегу добавляется скорость срабатывания × задержка.</translation>
    </message>
    <message>
        <source>Pretravel</source>
        <translation>Предход</translation>
    </message>
    <message>
        <source>Mechanical pretravel from first contact to the trigger threshold (typically 1-50 µm). Independent of speed and removed by calibration; adds to the overtravel and takes pretravel / speed.</source>
        <translation>Механический предход от первого контакта до порога срабатывания (обычно 1–50 мкм). Не зависит от скорости и убирается калибровкой; входит в перебег и занимает время предход / скорость.</translation>
    </message>
    <message>
        <source>µm</source>
        <translation>мкм</translation>
    </message>
    <message>
        <source>Interface response time</source>
        <translation>Время отклика интерфейса</translation>
    </message>
    <message>
        <source>Time the probe interface (receiver) needs to pass the trigger to the control. Constant, so calibration removes it from the measured value, but it adds trigger speed × delay to the overtravel.</source>
        <translation>Время, за которое интерфейс (приёмник) датчика передаёт сигнал срабатывания в ЧПУ. Оно постоянно, поэтому калибровка убирает его из измеренного значения, но к перебегу добавляется скорость срабатывания × задержка.</translation>
    </message>
    <message>
        <source>Repeatability (2σ)</source>
        <translation>Повторяемость (2σ)</translation>
    </message>
    <message>
        <source>Overtravel limit</source>
        <translation>Предел перебега</translation>
    </message>
    <message>
        <source>Stylus deflection range of the probe in the probing direction. The axis must stop within it or the probe or stylus is damaged; short styli along Z and small bores are the critical cases.</source>
        <translation>Допустимый отклон наконечника щупа в направлении измерения. Ось должна остановиться в его пределах, иначе датчик или наконечник будет повреждён; критичны короткие наконечники по Z и малые отверстия.</translation>
    </message>
    <message>
        <source>mm</source>
        <translation>мм</translation>
    </message>
    <message>
        <source>Reseat distance</source>
        <translation>Путь восстановления датчика</translation>
    </message>
    <message>
        <source>Distance the probe needs to reseat after a trigger. The two-touch backoff must clear the first touch&apos;s overtravel plus this.</source>
        <translation>Путь, необходимый датчику для восстановления после срабатывания. Отвод при двукратном касании должен перекрывать перебег первого касания плюс этот путь.</translation>
    </message>
    <message>
        <source>Calibration feed</source>
        <translation>Подача калибровки</translation>
    </message>
    <message>
        <source>Feed at which the probe was calibrated. Measuring at another feed shifts the delay travel and so the measured value; 0 means calibrated at the measuring feed.</source>
        <translation>Подача, на которой датчик калибровали. Измерение на другой подаче смещает путь за время задержки, а значит и измеренное значение; 0 — калибровка на измерительной подаче.</translation>
    </message>
    <message>
        <source>measuring feed</source>
        <translation>измерит. подача</translation>
    </message>
    <message>
        <source>Feature size</source>
        <translation>Размер элемента</translation>
    </message>
    <message>
        <source>Approach distance</source>
        <translation>Расстояние подхода</translation>
    </message>
    <message>
        <source>Start distance in front of the nominal surface. Must cover the part&apos;s position uncertainty, and should cover the distance needed to reach the feed so the touch happens at full speed. Approached at the probing feed, returned at the return feed.</source>
        <translation>Расстояние от начальной точки до номинальной поверхности. Должно перекрывать неопределённость положения детали и путь разгона до подачи, чтобы касание происходило на полной скорости. Подход — на подаче поиска, возврат — на подаче возврата.</translation>
    </message>
    <message>
        <source>Probing feedrate</source>
        <translation>Скорость подачи поиска</translation>
    </message>
    <message>
        <source>Feed of the (first) touch; single-touch measures at it. A higher feed shortens the approach but lengthens the braking, the overtravel and the return, and raises the single-touch uncertainty.</source>
        <translation>Подача (первого) касания; однократное касание измеряет на ней. Большая подача сокращает подход, но удлиняет торможение, перебег и возврат и увеличивает неопределённость однократного касания.</translation>
    </message>
    <message>
        <source>Measuring feedrate</source>
        <translation>Измерительная подача</translation>
    </message>
    <message>
        <source>Backoff</source>
        <translation>Отвод</translation>
    </message>
    <message>
        <source>Return feedrate</source>
        <translation>Подача возврата</translation>
    </message>
    <message>
        <source>Feed of the backoff and of the return to the start position (start distance plus overtravel).</source>
        <translation>Подача отвода и возврата в начальную точку (расстояние подхода плюс перебег).</translation>
    </message>
    <message>
        <source>Target uncertainty</source>
        <translation>Целевая неопределённость</translation>
    </message>
    <message>
        <source>none</source>
        <translation>нет</translation>
    </message>
    <message>
        <source>Single-touch</source>
        <translation>Однократное</translation>
    </message>
    <message>
        <source>Two-touch</source>
        <translation>Двукратное</translation>
    </message>
    <message>
        <source>Surface (1 touch)</source>
        <translation>Плоскость (1 кас.)</translation>
    </message>
    <message>
        <source>Web (2 touches)</source>
        <translation>Стенка (2 кас.)</translation>
    </message>
    <message>
        <source>Pocket (2 touches)</source>
        <translation>Паз (2 кас.)</translation>
    </message>
    <message>
        <source>Bore (4 touches)</source>
        <translation>Отверстие (4 кас.)</translation>
    </message>
    <message>
        <source>Boss (4 touches)</source>
        <translation>Бобышка (4 кас.)</translation>
    </message>
    <message>
        <source>Machine</source>
        <translation>Станок</translation>
    </message>
    <message>
        <source>Probe</source>
        <translation>Датчик</translation>
    </message>
    <message>
        <source>Cycle</source>
        <translation>Цикл</translation>
    </message>
    <message>
        <source>s</source>
        <translation>с</translation>
    </message>
    <message>
        <source>Constant accel.</source>
        <translation>Пост. ускорение</translation>
    </message>
    <message>
        <source>S-curve (jerk)</source>
        <translation>S-кривая (рывок)</translation>
    </message>
    <message>
        <source>µs</source>
        <translation>мкс</translation>
    </message>
    <message>
        <source>Time constant (T)</source>
        <translation>Постоянная T</translation>
    </message>
    <message>
        <source>Acceleration model</source>
        <translation>Модель разгона</translation>
    </message>
    <message>
        <source>The control latches (or timestamps) the position in hardware at the trigger: the scan-period wait leaves the measured value, but not the travel - the machine still stops late.</source>
        <translation>ЧПУ аппаратно защёлкивает (или отмечает временем) положение в момент срабатывания: ожидание опроса уходит из измеренного значения, но не из пути — станок всё равно останавливается поздно.</translation>
    </message>
    <message>
        <source>Latched (hardware-captured) input</source>
        <translation>Вход с защёлкой (аппаратной)</translation>
    </message>
    <message>
        <source>Single-touch measures at the probing feed. Two-touch finds the surface fast, backs off, and measures with a slow second touch.</source>
        <translation>Однократное касание измеряет на подаче поиска. Двукратное быстро находит поверхность, отводится и измеряет медленным вторым касанием.</translation>
    </message>
    <message>
        <source>Strategy</source>
        <translation>Стратегия</translation>
    </message>
    <message>
        <source>Feature</source>
        <translation>Элемент</translation>
    </message>
    <message>
        <source>The knee is the lowest probing feed whose cycle time is within this fraction of the fastest cycle, among the feeds whose overtravel stays within the probe&apos;s limit. Faster than the knee buys little time for more overtravel and uncertainty.</source>
        <translation>Точка излома — наименьшая подача поиска, при которой время цикла отличается от самого быстрого цикла не больше чем на эту долю; учитываются только подачи, при которых перебег не выходит за предел щупа. Подача выше излома почти не экономит время, но увеличивает перебег и неопределённость.</translation>
    </message>
    <message>
        <source>Knee tolerance</source>
        <translation>Допуск точки излома</translation>
    </message>
    <message>
        <source>%</source>
        <translation>%</translation>
    </message>
    <message>
        <source>Two-touch: distance the probe backs off after the first touch, from where it stopped or from the recorded trigger position (Backoff from). It must leave the second touch room to reseat the probe and to reach the measuring feed; any more is approached again at the slow measuring feed and wasted.</source>
        <translation>Двукратное касание: расстояние отвода датчика после первого касания — от точки остановки или от записанной точки срабатывания («Отвод от»). Оно должно оставить второму касанию место для восстановления датчика и для разгона до измерительной подачи; всё сверх этого снова проходится на медленной измерительной подаче и теряется.</translation>
    </message>
    <message>
        <source>Two-touch: where the backoff is measured from. stop: from where the probe stopped after the first touch (Renishaw&apos;s cycles). trigger: from the trigger position the control recorded (the skip position a macro reads); the axis then moves back its overtravel beyond that position as well.</source>
        <translation>Двукратное касание: от какой точки отсчитывается отвод. stop: от точки, где датчик остановился после первого касания (циклы Renishaw). trigger: от точки срабатывания, записанной ЧПУ (позиция пропуска, которую читает макрос); тогда ось дополнительно отходит на перебег за этой точкой.</translation>
    </message>
    <message>
        <source>Backoff from</source>
        <translation>Отвод от</translation>
    </message>
    <message>
        <source>Where it stopped</source>
        <translation>Точки остановки</translation>
    </message>
    <message>
        <source>Trigger position</source>
        <translation>Точки срабатывания</translation>
    </message>
    <message>
        <source>Rapid feed: a boss or web lifts over its wall at it, away from the part. Moves toward the part are protected, at the positioning feed.</source>
        <translation>Ускоренная подача: на ней щуп поднимается над стенкой бобышки или перемычки, прочь от детали. Перемещения к детали защищённые, на подаче позиционирования.</translation>
    </message>
    <message>
        <source>Positioning feed</source>
        <translation>Подача позиционирования</translation>
    </message>
    <message>
        <source>Boss or web: height the probe lifts above the measuring depth to pass over the wall between touches (up at the rapid feed, down at the positioning feed).</source>
        <translation>Бобышка или перемычка: высота подъёма щупа над глубиной измерения, чтобы пройти над стенкой между касаниями (вверх на ускоренной подаче, вниз на подаче позиционирования).</translation>
    </message>
    <message>
        <source>Clearance height</source>
        <translation>Высота безопасного подъёма</translation>
    </message>
    <message>
        <source>How the control accelerates before interpolation: a time constant (a = v/T, common on many controls), a constant acceleration, a jerk-limited S-curve, or none (the feed is commanded at once and stopped at once, as on a skip block without acc/dec; then the filter after interpolation and the servo shape the motion). Sets every move time and the braking distance after the trigger.</source>
        <translation>Как система ЧПУ разгоняет ось до интерполяции: постоянная времени (a = v/T, распространена на многих системах), постоянное ускорение, S-кривая с ограничением рывка или без разгона (подача задаётся сразу и снимается сразу, как в кадре пропуска без разгона/торможения; тогда движение формируют фильтр после интерполяции и сервопривод). Определяет время каждого перемещения и тормозной путь после срабатывания.</translation>
    </message>
    <message>
        <source>Acc/dec filter after interpolation: none, linear (a moving average of the commanded speed over the filter time), exponential (first order, time constant = the filter time) or bell (two moving averages, the filter time and the second filter time). After the trigger the axis drains it: v*T/2 more (linear), v*T (exponential), v*(T1+T2)/2 (bell).</source>
        <translation>Фильтр разгона/торможения после интерполяции: нет, линейный (скользящее среднее заданной скорости за время фильтра), экспоненциальный (первого порядка, постоянная времени = время фильтра) или колоколообразный (два скользящих средних: время фильтра и второе время фильтра). После срабатывания ось дорабатывает фильтр: ещё v*T/2 (линейный), v*T (экспоненциальный), v*(T1+T2)/2 (колоколообразный).</translation>
    </message>
    <message>
        <source>Filter after interpolation</source>
        <translation>Фильтр после интерполяции</translation>
    </message>
    <message>
        <source>Time of the filter after interpolation: the linear filter&apos;s window, the exponential filter&apos;s time constant, or the bell filter&apos;s first window (Fanuc: the cutting-feed acc/dec time constant).</source>
        <translation>Время фильтра после интерполяции: окно линейного фильтра, постоянная времени экспоненциального или первое окно колоколообразного (Fanuc: постоянная времени разгона/торможения рабочей подачи).</translation>
    </message>
    <message>
        <source>Filter time</source>
        <translation>Время фильтра</translation>
    </message>
    <message>
        <source>Second window of the bell filter after interpolation (the S-shaping time).</source>
        <translation>Второе окно колоколообразного фильтра после интерполяции (время S-сглаживания).</translation>
    </message>
    <message>
        <source>Second filter time</source>
        <translation>Второе время фильтра</translation>
    </message>
    <message>
        <source>Servo time constant Tp = 1/Kv (position loop gain): the axis trails the command by v*Tp and, after the command stops, travels that much more. 0 = the axis follows the command exactly.</source>
        <translation>Постоянная времени сервопривода Tp = 1/Kv (коэффициент контура положения): ось отстаёт от задания на v*Tp и после остановки задания проходит ещё столько же. 0 — ось точно следует заданию.</translation>
    </message>
    <message>
        <source>Servo time constant</source>
        <translation>Постоянная времени сервопривода</translation>
    </message>
    <message>
        <source>In-position width: with a filter or a servo lag, a move counts as done when the axis is within this of its commanded end, and the next move starts then. The overtravel is still where the axis comes to rest.</source>
        <translation>Зона контроля достижения позиции: при фильтре или запаздывании сервопривода перемещение считается завершённым, когда ось ближе этой величины к заданному концу, и тогда начинается следующее. Перебег по-прежнему считается до точки, где ось останавливается.</translation>
    </message>
    <message>
        <source>In-position width</source>
        <translation>Зона достижения позиции</translation>
    </message>
    <message>
        <source>ideal servo</source>
        <translation>идеальный привод</translation>
    </message>
    <message>
        <source>None (feed at once)</source>
        <translation>Нет (подача сразу)</translation>
    </message>
    <message>
        <source>None</source>
        <translation>Нет</translation>
    </message>
    <message>
        <source>Linear (moving average)</source>
        <translation>Линейный (ср. за окно)</translation>
    </message>
    <message>
        <source>Exponential</source>
        <translation>Экспоненциальный</translation>
    </message>
    <message>
        <source>Bell (two averages)</source>
        <translation>Колокол (2 ср.)</translation>
    </message>
    <message>
        <source>The probe maker&apos;s rated maximum probing speed. A touch faster than it is an error: the probe may not trigger reliably or may be damaged. 0 means no limit.</source>
        <translation>Максимальная скорость ощупывания по паспорту производителя щупа. Касание быстрее неё — ошибка: щуп может срабатывать ненадёжно или повредиться. 0 — без ограничения.</translation>
    </message>
    <message>
        <source>Probe&apos;s maximum feed</source>
        <translation>Макс. подача щупа</translation>
    </message>
    <message>
        <source>Part position uncertainty</source>
        <translation>Неопределённость положения детали</translation>
    </message>
    <message>
        <source>How many times the measuring touch is made and averaged (two-touch: back off and touch again at the measuring feed; single-touch: back to the start and touch again). The random parts of the uncertainty, scan phase and repeatability, fall by the square root of this; each repeat adds its moves to the cycle. A whole number.</source>
        <translation>Сколько раз выполняется измерительное касание с усреднением (два касания: отвод и повторное касание на измерительной подаче; одно касание: возврат в начало и повторное касание). Случайные составляющие неопределённости — фаза опроса и повторяемость — уменьшаются в корень из этого числа раз; каждый повтор добавляет свои перемещения к циклу. Целое число.</translation>
    </message>
    <message>
        <source>Measurements</source>
        <translation>Число измерений</translation>
    </message>
    <message>
        <source>Parts made per year, for the savings: time saved per part times this. 0 means savings are not shown.</source>
        <translation>Деталей в год, для расчёта экономии: сэкономленное время на деталь, умноженное на это число. 0 — экономия не показывается.</translation>
    </message>
    <message>
        <source>Parts per year</source>
        <translation>Деталей в год</translation>
    </message>
    <message>
        <source>How many times this probing cycle runs per part, for the savings. 0 means savings are not shown.</source>
        <translation>Сколько раз этот цикл измерения выполняется на одну деталь, для расчёта экономии. 0 — экономия не показывается.</translation>
    </message>
    <message>
        <source>Cycles per part</source>
        <translation>Циклов на деталь</translation>
    </message>
    <message>
        <source>What an hour of the machine costs, in any currency, for the savings per year. 0 means the savings are shown in hours only.</source>
        <translation>Стоимость часа работы станка в любой валюте, для экономии за год. 0 — экономия показывается только в часах.</translation>
    </message>
    <message>
        <source>Machine rate per hour</source>
        <translation>Стоимость станко-часа</translation>
    </message>
    <message>
        <source>no limit</source>
        <translation>без ограничения</translation>
    </message>
    <message>
        <source>known part</source>
        <translation>известна</translation>
    </message>
    <message>
        <source>×</source>
        <translation>×</translation>
    </message>
    <message>
        <source>/year</source>
        <translation>/год</translation>
    </message>
    <message>
        <source>not shown</source>
        <translation>не показывать</translation>
    </message>
    <message>
        <source>/part</source>
        <translation>/деталь</translation>
    </message>
    <message>
        <source>/h</source>
        <translation>/ч</translation>
    </message>
    <message>
        <source>hours only</source>
        <translation>только часы</translation>
    </message>
    <message>
        <source>How far each probing move searches past the farthest place its surface can be (the nominal surface plus the part position uncertainty; for a second touch or a repeat, where the touch before stopped) before the control gives up. It must reach past the touch&apos;s stop: a search that ends sooner is braking when it touches, triggers below the feed and stops at its end. 0 means automatic: halfway from the touch&apos;s stop to the probe&apos;s overtravel limit.</source>
        <translation>Насколько каждое перемещение поиска продолжается за самое дальнее возможное положение поверхности (номинальная поверхность плюс неопределённость положения детали; для второго касания или повтора — точка остановки предыдущего касания), прежде чем система ЧПУ прекратит поиск. Поиск должен заканчиваться за точкой остановки касания: поиск, который заканчивается раньше, касается уже при торможении, срабатывает на скорости ниже подачи и останавливается в конце поиска. 0 — автоматически: посередине между точкой остановки касания и пределом перебега щупа.</translation>
    </message>
    <message>
        <source>Search beyond surface</source>
        <translation>Поиск за поверхностью</translation>
    </message>
    <message>
        <source>automatic</source>
        <translation>автоматически</translation>
    </message>
    <message>
        <source>Time the control adds at each block change, after a move ends and before the next starts: block processing, the wait for the in-position check and, after a probing move, for the skip position to be read. Every move of the cycle (touches, backoffs, returns, positioning moves) adds it once. 0 means none.</source>
        <translation>Время, которое система ЧПУ добавляет при каждой смене кадра — после окончания перемещения и до начала следующего: обработка кадра, ожидание контроля достижения позиции и, после измерительного перемещения, чтения позиции пропуска. Каждое перемещение цикла (касания, отводы, возвраты, позиционирование) добавляет его один раз. 0 — нет.</translation>
    </message>
    <message>
        <source>Block change time</source>
        <translation>Время смены кадра</translation>
    </message>
    <message>
        <source>Period at which the control scans the skip input (about 4 ms on a standard input, 4 µs on a high-speed input). The wait for the next scan, from nothing to a full period, is the single-touch uncertainty (trigger speed × scan period); the overtravel takes the worst case, a full period of travel, and the cycle time the mean wait, half a period.</source>
        <translation>Период, с которым ЧПУ опрашивает вход пропуска (около 4 мс на стандартном входе, 4 мкс на быстром). Ожидание следующего опроса, от нуля до целого периода, даёт неопределённость однократного касания (скорость срабатывания × период опроса); в перебег входит худший случай, путь за целый период, а во время цикла — среднее ожидание, полпериода.</translation>
    </message>
    <message>
        <source>A surface needs one touch, a web or pocket two opposite touches, a bore or boss four; the probe moves out from the feature&apos;s centre to each touch and back at the positioning feed.</source>
        <translation>Плоскости нужно одно касание, стенке или пазу — два противоположных, отверстию или бобышке — четыре; щуп выходит из центра элемента к каждому касанию и возвращается обратно на подаче позиционирования.</translation>
    </message>
    <message>
        <source>Distance between opposite stylus-centre contact points: web or pocket width, bore or boss diameter less the ball diameter. Sets the positioning moves out from the centre to each touch and back; unused for a surface.</source>
        <translation>Расстояние между противоположными точками контакта по центру шарика: ширина стенки или паза, диаметр отверстия или бобышки минус диаметр шарика. Определяет позиционирующие перемещения от центра к каждому касанию и обратно; для плоскости не используется.</translation>
    </message>
    <message>
        <source>Feed of the second, measuring touch of two-touch (typically 30 mm/min). Sets the two-touch uncertainty; the second approach, the backoff less where the first touch stopped (on average), is travelled at it.</source>
        <translation>Подача второго, измерительного касания при двукратном касании (обычно 30 мм/мин). Определяет неопределённость двукратного касания; на ней проходится второй подвод: отвод за вычетом среднего перебега первого касания.</translation>
    </message>
    <message>
        <source>Web, pocket, bore, boss: feed of the protected positioning moves (probe armed, so a collision stops the axis) from the feature&apos;s centre out to each touch and back to the centre.</source>
        <translation>Перемычка, паз, отверстие, бобышка: подача защищённых позиционирующих перемещений (датчик включён, столкновение останавливает ось) от центра элемента к каждому касанию и обратно к центру.</translation>
    </message>
    <message>
        <source>The highest feed override the operator may turn the cycle up to. Feed override speeds up every move at feed, the touches and the protected positioning moves too, so every overtravel check holds at it: the stylus&apos;s limit, the searches past each stop and the backoff that must clear the first touch&apos;s stop. The cycle time is at 100 %. 120 % is as far as every common control&apos;s dial turns; set what your machine&apos;s panel allows (Fanuc-type and Heidenhain 150 %, Haas 200 %), or 100 where the program locks the override.</source>
        <translation>Наибольшая коррекция подачи, до которой оператор может поднять цикл. Коррекция ускоряет каждое перемещение на подаче, в том числе касания и защищённые позиционирующие перемещения, поэтому все проверки перебега выполняются при ней: предел щупа, поиски за каждой остановкой и отвод, который должен освободить остановку первого касания. Время цикла — при 100 %. До 120 % поворачивается переключатель любой распространённой системы ЧПУ; задайте то, что позволяет пульт вашего станка (типа Fanuc и Heidenhain — 150 %, Haas — 200 %), или 100, если программа блокирует коррекцию.</translation>
    </message>
    <message>
        <source>Highest feed override</source>
        <translation>Наибольшая коррекция подачи</translation>
    </message>
    <message>
        <source>Web, pocket, bore, boss: the cycle program checks the measured size (width or diameter) against the feature size plus or minus this, and the import does the same. 0 means no check.</source>
        <translation>Стенка, паз, отверстие, бобышка: программа цикла сравнивает измеренный размер (ширину или диаметр) с размером элемента плюс-минус это значение; импорт делает то же. 0 — без проверки.</translation>
    </message>
    <message>
        <source>Size tolerance</source>
        <translation>Допуск на размер</translation>
    </message>
    <message>
        <source>What the cycle program does when the measured size is outside its tolerance. flag: sets its out-of-tolerance variable and writes OUT OF TOLERANCE to its log, then goes on. stop: the same, then stops with an alarm.</source>
        <translation>Что делает программа цикла, когда измеренный размер вне допуска. flag: устанавливает переменную выхода за допуск и пишет OUT OF TOLERANCE в журнал, затем продолжает. stop: то же, затем останавливается с аварийным сообщением.</translation>
    </message>
    <message>
        <source>Flag it and go on</source>
        <translation>Отметить и продолжить</translation>
    </message>
    <message>
        <source>Stop with an alarm</source>
        <translation>Остановить с аварийным сообщением</translation>
    </message>
    <message>
        <source>If out of tolerance</source>
        <translation>Если вне допуска</translation>
    </message>
    <message>
        <source>Unidirectional positioning repeatability of the axes, 2 sigma, from the machine&apos;s acceptance test (ISO 230-2 states R = 4 sigma: enter R/2). A term of the uncertainty budget: u = value/2, the same for repeated touches.</source>
        <translation>Односторонняя повторяемость позиционирования осей, 2 сигма, из приёмочных испытаний станка (ISO 230-2 даёт R = 4 сигма: введите R/2). Член бюджета неопределённости: u = значение/2, одинаков для повторных касаний.</translation>
    </message>
    <message>
        <source>Positioning repeatability (2σ)</source>
        <translation>Повторяемость позиционирования (2σ)</translation>
    </message>
    <message>
        <source>How far the machine&apos;s and the part&apos;s temperature may move the measured point between calibration and measurement, ± (measure it: probe an artefact again after the time a batch takes). A term of the uncertainty budget: u = value/√3, the same for repeated touches.</source>
        <translation>Насколько температура станка и детали может сместить измеряемую точку между калибровкой и измерением, ± (измерьте: повторно промерьте эталон через время обработки партии). Член бюджета неопределённости: u = значение/√3, одинаков для повторных касаний.</translation>
    </message>
    <message>
        <source>Thermal drift (±)</source>
        <translation>Температурный дрейф (±)</translation>
    </message>
    <message>
        <source>Unidirectional repeatability of the probe, 2 sigma. A term of the uncertainty budget with the scan-period range: u = value/2, averaged over repeated touches.</source>
        <translation>Односторонняя повторяемость датчика, 2 сигма. Член бюджета неопределённости вместе с разбросом периода опроса: u = значение/2, усредняется по повторным касаниям.</translation>
    </message>
    <message>
        <source>Pretravel variation over the directions the cycle probes that calibration leaves, ± (the data sheet&apos;s 2D lobing: about 1 µm for a kinematic probe, 0.25 µm for a strain-gauge one; 0 when the probe is calibrated in every direction it measures). A term of the uncertainty budget: u = value/√3, the same for repeated touches.</source>
        <translation>Изменение предхода по направлениям измерения цикла, оставшееся после калибровки, ± (лепестковость 2D из паспорта: около 1 мкм у кинематического датчика, 0,25 мкм у тензометрического; 0, если датчик откалиброван в каждом направлении измерения). Член бюджета неопределённости: u = значение/√3, одинаков для повторных касаний.</translation>
    </message>
    <message>
        <source>Lobing (±)</source>
        <translation>Лепестковость (±)</translation>
    </message>
    <message>
        <source>Expanded uncertainty (k = 2) of the artefact the probe is calibrated on, from its calibration certificate (a ring gauge&apos;s diameter, a gauge block&apos;s length). A term of the uncertainty budget: u = value/2, the same for repeated touches.</source>
        <translation>Расширенная неопределённость (k = 2) эталона, на котором калибруется датчик, из его сертификата калибровки (диаметр установочного кольца, длина концевой меры). Член бюджета неопределённости: u = значение/2, одинаков для повторных касаний.</translation>
    </message>
    <message>
        <source>Calibration artefact (k = 2)</source>
        <translation>Эталон калибровки (k = 2)</translation>
    </message>
    <message>
        <source>How far the surface may lie from its nominal position (a casting, a part clamped by hand). The start distance must cover it plus the distance to reach the probing feed, so the touch is at full feed wherever the part lies. 0 means a known part: its surface is where the drawing puts it.</source>
        <translation>Насколько поверхность может отстоять от номинального положения (отливка, деталь, закреплённая вручную). Начальное расстояние должно покрывать эту величину плюс путь разгона до подачи поиска, чтобы касание происходило на полной подаче, где бы ни лежала деталь. 0 — известная деталь: её поверхность там, где её задаёт чертёж.</translation>
    </message>
    <message>
        <source>Target for the expanded (k = 2) uncertainty of the measured point, the whole budget (the trigger&apos;s part and the terms no feed changes); a warning appears above it. 0 means no target.</source>
        <translation>Цель для расширенной неопределённости (k = 2) измеряемой точки по всему бюджету (доля срабатывания и члены, не зависящие от подачи); выше неё выдаётся предупреждение. 0 — цели нет.</translation>
    </message>
    <message>
        <source>The shortest start distance the optimiser proposes: no touch starts closer to its nominal surface, whatever the part position uncertainty and the feed allow. 0 means no minimum.</source>
        <translation>Наименьшее начальное расстояние, которое предлагает оптимизатор: ни одно касание не начинается ближе к номинальной поверхности, что бы ни допускали неопределённость положения детали и подача. 0 — без минимума.</translation>
    </message>
    <message>
        <source>Shortest approach</source>
        <translation>Наименьшее расстояние подхода</translation>
    </message>
    <message>
        <source>The slowest probing or measuring feed the optimiser proposes (the probe maker&apos;s or the shop&apos;s slowest probing speed); with the probe&apos;s maximum feed and the rapid feed it bounds every feed the optimiser tries.</source>
        <translation>Наименьшая подача поиска или измерения, которую предлагает оптимизатор (наименьшая скорость измерения по данным изготовителя датчика или правилам цеха); вместе с максимальной подачей датчика и ускоренной подачей она ограничивает все подачи, которые пробует оптимизатор.</translation>
    </message>
    <message>
        <source>Slowest feed</source>
        <translation>Наименьшая подача</translation>
    </message>
</context>
<context>
    <name>PdfReport</name>
    <message>
        <source>Page %1 of %2</source>
        <translation>Страница %1 из %2</translation>
    </message>
</context>
<context>
    <name>Phase</name>
    <message>
        <source>Approach</source>
        <translation>Подход</translation>
    </message>
    <message>
        <source>Pretravel</source>
        <translation>Предход</translation>
    </message>
    <message>
        <source>Deceleration</source>
        <translation>Торможение</translation>
    </message>
    <message>
        <source>Backoff</source>
        <translation>Отвод</translation>
    </message>
    <message>
        <source>2nd approach</source>
        <translation>2-й подход</translation>
    </message>
    <message>
        <source>2nd pretravel</source>
        <translation>2-й предход</translation>
    </message>
    <message>
        <source>2nd deceleration</source>
        <translation>2-е торможение</translation>
    </message>
    <message>
        <source>Return</source>
        <translation>Возврат</translation>
    </message>
    <message>
        <source>Positioning</source>
        <translation>Позиционирование</translation>
    </message>
    <message>
        <source>Interface delay</source>
        <translation>Задержка интерф.</translation>
    </message>
    <message>
        <source>Controller delay</source>
        <translation>Задержка ЧПУ</translation>
    </message>
    <message>
        <source>2nd interface delay</source>
        <translation>2-я задержка интерф.</translation>
    </message>
    <message>
        <source>2nd controller delay</source>
        <translation>2-я задержка ЧПУ</translation>
    </message>
    <message>
        <source>Lift</source>
        <translation>Подъём</translation>
    </message>
    <message>
        <source>Lower</source>
        <translation>Опускание</translation>
    </message>
    <message>
        <source>Block changes</source>
        <translation>Смены кадров</translation>
    </message>
</context>
<context>
    <name>Preset</name>
    <message>
        <source>Fanuc-type: exponential acc/dec after interpolation + servo</source>
        <translation>Типа Fanuc: экспоненциальный разгон/торможение после интерполяции + сервопривод</translation>
    </message>
    <message>
        <source>The skip feed is commanded at once and smoothed after interpolation by an exponential filter (32 ms), then a servo lag (33 ms); 20 ms from trigger to reaction with the probe&apos;s 2 ms. Overtravel at cruise: F/60 × (20 + Tc + Ts) / 1000 mm. Typical values: replace them with your machine&apos;s.</source>
        <translation>Подача пропуска задаётся сразу и сглаживается после интерполяции экспоненциальным фильтром (32 мс), затем запаздывание сервопривода (33 мс); 20 мс от срабатывания до реакции вместе с 2 мс щупа. Перебег на установившейся подаче: F/60 × (20 + Tc + Ts) / 1000 мм. Типичные значения: замените их значениями вашего станка.</translation>
    </message>
    <message>
        <source>High-speed skip input (4 µs scan)</source>
        <translation>Быстрый вход пропуска (опрос 4 мкс)</translation>
    </message>
    <message>
        <source>A direct, high-speed skip input scanned every 4 µs with a 0.5 ms latency. Typical values: replace them with your machine&apos;s.</source>
        <translation>Прямой быстрый вход пропуска с опросом каждые 4 мкс и задержкой 0,5 мс. Типовые значения: замените их значениями вашего станка.</translation>
    </message>
    <message>
        <source>Latched input (position captured in hardware)</source>
        <translation>Вход с защёлкой (положение фиксируется аппаратно)</translation>
    </message>
    <message>
        <source>The control latches the axis positions at the trigger: the scan wait leaves the measured value but not the travel. Typical values: replace them with your machine&apos;s.</source>
        <translation>ЧПУ защёлкивает положения осей в момент срабатывания: ожидание опроса уходит из измеренного значения, но не из пути. Типовые значения: замените их значениями вашего станка.</translation>
    </message>
    <message>
        <source>Linear acc/dec after interpolation</source>
        <translation>Линейный разгон/торможение после интерполяции</translation>
    </message>
    <message>
        <source>The feed is commanded at once and averaged over 64 ms after interpolation, then a 20 ms servo lag: a touch during the ramp does not brake at once. Typical values: replace them with your machine&apos;s.</source>
        <translation>Подача задаётся сразу и усредняется за 64 мс после интерполяции, затем запаздывание сервопривода 20 мс: касание во время разгона не тормозит ось сразу. Типичные значения: замените их значениями вашего станка.</translation>
    </message>
    <message>
        <source>LinuxCNC (1 ms servo period)</source>
        <translation>LinuxCNC (период сервоцикла 1 мс)</translation>
    </message>
    <message>
        <source>LinuxCNC 2.9 in exact stop (G61.1), as ProbeCycle&apos;s programs run it: constant acceleration (1000 mm/s²), the probe input read once per 1 ms servo period and braking two periods later, no filter after interpolation, ideal drives. Typical values: replace them with your machine&apos;s, or read them from its INI file with File &gt; Import Machine.</source>
        <translation>LinuxCNC 2.9 в режиме точного останова (G61.1), как его используют программы ProbeCycle: постоянное ускорение (1000 мм/с²), вход щупа опрашивается раз в период сервоцикла 1 мс, торможение начинается двумя периодами позже, без фильтра после интерполяции, идеальные приводы. Типичные значения: замените их значениями вашего станка или прочитайте их из его INI-файла через «Файл &gt; Импорт станка».</translation>
    </message>
    <message>
        <source>Mitsubishi-type: G31 without acc/dec</source>
        <translation>Типа Mitsubishi: G31 без разгона/торможения</translation>
    </message>
    <message>
        <source>The skip block moves without acceleration: the command starts and stops at once and only the servo lag (Tp = 30 ms) smooths it; 5 ms response delay with the probe&apos;s 2 ms, 1 ms scan. Overtravel: F/60 × (Tp + t1 ± t2). Typical values: replace them with your machine&apos;s.</source>
        <translation>Кадр пропуска выполняется без разгона: задание начинается и прекращается сразу, сглаживает его только запаздывание сервопривода (Tp = 30 мс); задержка отклика 5 мс вместе с 2 мс щупа, опрос 1 мс. Перебег: F/60 × (Tp + t1 ± t2). Типичные значения: замените их значениями вашего станка.</translation>
    </message>
    <message>
        <source>Standard skip input (4 ms scan)</source>
        <translation>Стандартный вход пропуска (опрос 4 мс)</translation>
    </message>
    <message>
        <source>A skip input scanned every 4 ms with a 2 ms latency, on a time-constant machine (T = 60 ms) without a filter after interpolation or servo lag. Typical values: replace them with your machine&apos;s.</source>
        <translation>Вход пропуска с опросом каждые 4 мс и задержкой 2 мс на станке с постоянной времени (T = 60 мс), без фильтра после интерполяции и без запаздывания сервопривода. Типичные значения: замените их значениями вашего станка.</translation>
    </message>
    <message>
        <source>Kinematic probe, optical transmission</source>
        <translation>Кинематический датчик, оптическая передача</translation>
    </message>
    <message>
        <source>Resistive kinematic probe with an optical receiver: 5 µm pretravel, 2 ms interface response, 1 µm repeatability. Typical values: replace them with the ones you measure.</source>
        <translation>Резистивный кинематический датчик с оптическим приёмником: предход 5 мкм, отклик интерфейса 2 мс, повторяемость 1 мкм. Типовые значения: замените их измеренными.</translation>
    </message>
    <message>
        <source>Kinematic probe, radio transmission</source>
        <translation>Кинематический датчик, радиопередача</translation>
    </message>
    <message>
        <source>Kinematic probe with a radio receiver: the transmission adds about 10 ms of interface response. Typical values: replace them with the ones you measure.</source>
        <translation>Кинематический датчик с радиоприёмником: передача добавляет около 10 мс к отклику интерфейса. Типовые значения: замените их измеренными.</translation>
    </message>
    <message>
        <source>Short stylus / small bore (2 mm overtravel)</source>
        <translation>Короткий наконечник / малое отверстие (перебег 2 мм)</translation>
    </message>
    <message>
        <source>A probe with a short stylus or in a small bore, where only about 2 mm of overtravel is safe. Typical values: replace them with the ones you measure.</source>
        <translation>Датчик с коротким наконечником или в малом отверстии, где безопасен перебег лишь около 2 мм. Типовые значения: замените их измеренными.</translation>
    </message>
    <message>
        <source>Strain-gauge probe (high accuracy)</source>
        <translation>Тензометрический датчик (высокая точность)</translation>
    </message>
    <message>
        <source>Strain-gauge probe: sub-micrometre pretravel and repeatability, low trigger force. Typical values: replace them with the ones you measure.</source>
        <translation>Тензометрический датчик: предход и повторяемость меньше микрометра, малое усилие срабатывания. Типовые значения: замените их измеренными.</translation>
    </message>
</context>
<context>
    <name>Program</name>
    <message>
        <source>the backoff %1 does not clear the first touch&apos;s overtravel %2: set cycle.backoff_mm to at least %3 (the recommended backoff)</source>
        <translation>отвод %1 не покрывает перебег первого касания %2: задайте cycle.backoff_mm не меньше %3 (рекомендуемый отвод)</translation>
    </message>
    <message>
        <source>the gauge (%1) leaves the ball (%2) no more room than the centre tolerance %3: a larger gauge or a smaller ball</source>
        <translation>кольцо (%1) оставляет шарику (%2) не больше места, чем допуск центра %3: нужно кольцо больше или шарик меньше</translation>
    </message>
    <message>
        <source>the plan turns the spindle to %1 deg; a %2 program turns it to 180 deg only, with the command given as --orient-180</source>
        <translation>план поворачивает шпиндель на %1°; программа %2 поворачивает его только на 180° командой, заданной в --orient-180</translation>
    </message>
    <message>
        <source>%1: the ring program turns the spindle to 180 deg, and %2 controls have no common word for that (M19 with an angle differs by maker and machine): give your control&apos;s command, e.g. &quot;M19 R180.&quot; if your manual says so; ProbeCycle does not guess it</source>
        <translation>%1: программа кольца поворачивает шпиндель на 180°, а у систем ЧПУ %2 нет общей команды для этого (M19 с углом различается у производителей и станков): укажите команду вашей системы ЧПУ, например &quot;M19 R180.&quot;, если так сказано в вашем руководстве; ProbeCycle её не угадывает</translation>
    </message>
    <message>
        <source>%1: got &apos;%2&apos;; allowed: one block of at most 60 upper-case letters, digits, spaces and . + - # [ ] =</source>
        <translation>%1: получено «%2»; допустимо: один кадр не длиннее 60 знаков из заглавных букв, цифр, пробелов и . + - # [ ] =</translation>
    </message>
    <message>
        <source>at %1 and up to %4 % feed override the model&apos;s overtravel is %2, at or over the probe&apos;s limit %3: lower the feed (or cycle.feed_override_max_pct) or check the scenario</source>
        <translation>при %1 и коррекции подачи до %4 % перебег по модели %2 — на пределе щупа %3 или выше: уменьшите подачу (или cycle.feed_override_max_pct) или проверьте сценарий</translation>
    </message>
    <message>
        <source>the plan records %1 touches; a %2 program keeps at most %3 (three common variables each, #%4 to #%5): use fewer feeds or repeats</source>
        <translation>план записывает касаний: %1; программа %2 хранит не больше %3 (по три общие переменные на касание, от #%4 до #%5): уменьшите число подач или повторов</translation>
    </message>
    <message>
        <source>%1: got %2; allowed: 1 or 2 (the probe&apos;s input), negative for a probe whose signal falls when it triggers: 1, -1, 2, -2</source>
        <translation>%1: получено %2; допустимо: 1 или 2 (вход щупа), со знаком минус для щупа, сигнал которого спадает при срабатывании: 1, -1, 2, -2</translation>
    </message>
</context>
<context>
    <name>ReportWord</name>
    <message>
        <source>Ring gauge</source>
        <translation>Кольцо</translation>
    </message>
    <message>
        <source>Circle fits by spindle orientation</source>
        <translation>Окружности по ориентациям шпинделя</translation>
    </message>
    <message>
        <source>Points</source>
        <translation>Точки</translation>
    </message>
    <message>
        <source>Length</source>
        <translation>Длина</translation>
    </message>
    <message>
        <source>Fit</source>
        <translation>Подбор</translation>
    </message>
    <message>
        <source>Groups</source>
        <translation>Группы</translation>
    </message>
    <message>
        <source>Feeds</source>
        <translation>Подачи</translation>
    </message>
    <message>
        <source>Touches</source>
        <translation>Касания</translation>
    </message>
    <message>
        <source>C axis</source>
        <translation>Ось C</translation>
    </message>
    <message>
        <source>Summary</source>
        <translation>Итог</translation>
    </message>
    <message>
        <source>Quantity</source>
        <translation>Величина</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Значение</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>Ед.</translation>
    </message>
    <message>
        <source>Uncertainty</source>
        <translation>Неопределённость</translation>
    </message>
    <message>
        <source>Count</source>
        <translation>Число</translation>
    </message>
    <message>
        <source>Min</source>
        <translation>Мин.</translation>
    </message>
    <message>
        <source>Max</source>
        <translation>Макс.</translation>
    </message>
    <message>
        <source>Mean</source>
        <translation>Среднее</translation>
    </message>
    <message>
        <source>RMS</source>
        <translation>СКЗ</translation>
    </message>
    <message>
        <source>Std. deviation</source>
        <translation>СКО</translation>
    </message>
    <message>
        <source>Gauge diameter</source>
        <translation>Диаметр кольца</translation>
    </message>
    <message>
        <source>Centre X</source>
        <translation>Центр X</translation>
    </message>
    <message>
        <source>Centre Y</source>
        <translation>Центр Y</translation>
    </message>
    <message>
        <source>Runout X</source>
        <translation>Биение X</translation>
    </message>
    <message>
        <source>Runout Y</source>
        <translation>Биение Y</translation>
    </message>
    <message>
        <source>Runout</source>
        <translation>Биение</translation>
    </message>
    <message>
        <source>Effective radius</source>
        <translation>Эффективный радиус</translation>
    </message>
    <message>
        <source>Radius X+</source>
        <translation>Радиус X+</translation>
    </message>
    <message>
        <source>Radius X-</source>
        <translation>Радиус X-</translation>
    </message>
    <message>
        <source>Radius Y+</source>
        <translation>Радиус Y+</translation>
    </message>
    <message>
        <source>Radius Y-</source>
        <translation>Радиус Y-</translation>
    </message>
    <message>
        <source>Largest residual</source>
        <translation>Наибольший остаток</translation>
    </message>
    <message>
        <source>Runout limit</source>
        <translation>Предел биения</translation>
    </message>
    <message>
        <source>Residual limit</source>
        <translation>Предел остатка</translation>
    </message>
    <message>
        <source>Spindle orientation</source>
        <translation>Ориентация шпинделя</translation>
    </message>
    <message>
        <source>Radius</source>
        <translation>Радиус</translation>
    </message>
    <message>
        <source>Line</source>
        <translation>Строка</translation>
    </message>
    <message>
        <source>Direction</source>
        <translation>Направление</translation>
    </message>
    <message>
        <source>Residual</source>
        <translation>Остаток</translation>
    </message>
    <message>
        <source>Surface Z</source>
        <translation>Z поверхности</translation>
    </message>
    <message>
        <source>Active length</source>
        <translation>Активная длина</translation>
    </message>
    <message>
        <source>Nominal length</source>
        <translation>Номинальная длина</translation>
    </message>
    <message>
        <source>Mean trigger Z</source>
        <translation>Среднее Z срабатывания</translation>
    </message>
    <message>
        <source>Range of trigger Z</source>
        <translation>Размах Z срабатывания</translation>
    </message>
    <message>
        <source>Effective length</source>
        <translation>Эффективная длина</translation>
    </message>
    <message>
        <source>Wear</source>
        <translation>Износ</translation>
    </message>
    <message>
        <source>Interpolation period</source>
        <translation>Период интерполяции</translation>
    </message>
    <message>
        <source>Group</source>
        <translation>Группа</translation>
    </message>
    <message>
        <source>Axis</source>
        <translation>Ось</translation>
    </message>
    <message>
        <source>Delay</source>
        <translation>Время задержки</translation>
    </message>
    <message>
        <source>Position at zero feed</source>
        <translation>Положение при нулевой подаче</translation>
    </message>
    <message>
        <source>Lag [cycles]</source>
        <translation>Запаздывание [циклов]</translation>
    </message>
    <message>
        <source>Compensation lag [cycles]</source>
        <translation>Запаздывание для компенсации [циклов]</translation>
    </message>
    <message>
        <source>Residual (2σ)</source>
        <translation>Остаток (2σ)</translation>
    </message>
    <message>
        <source>Feed</source>
        <translation>Подача</translation>
    </message>
    <message>
        <source>Mean deviation</source>
        <translation>Среднее отклонение</translation>
    </message>
    <message>
        <source>Fitted deviation</source>
        <translation>Подобранное отклонение</translation>
    </message>
    <message>
        <source>Range</source>
        <translation>Размах</translation>
    </message>
    <message>
        <source>Measured</source>
        <translation>Измерено</translation>
    </message>
    <message>
        <source>Axis X</source>
        <translation>Ось, X</translation>
    </message>
    <message>
        <source>Axis Y</source>
        <translation>Ось, Y</translation>
    </message>
    <message>
        <source>Angle</source>
        <translation>Угол</translation>
    </message>
    <message>
        <source>Point</source>
        <translation>Точка</translation>
    </message>
    <message>
        <source>Deviation</source>
        <translation>Отклонение</translation>
    </message>
    <message>
        <source>Direct deviation</source>
        <translation>Прямое отклонение</translation>
    </message>
    <message>
        <source>System error</source>
        <translation>Систем. погрешность</translation>
    </message>
    <message>
        <source>C-axis uncertainty</source>
        <translation>Неопределённость оси C</translation>
    </message>
    <message>
        <source>Tolerance</source>
        <translation>Допуск</translation>
    </message>
    <message>
        <source>Test part (on the machine)</source>
        <translation>Проверяемая деталь (на станке)</translation>
    </message>
    <message>
        <source>pasted</source>
        <translation>вставлены</translation>
    </message>
    <message>
        <source>deg</source>
        <translation>°</translation>
    </message>
    <message>
        <source>rad</source>
        <translation>рад</translation>
    </message>
    <message>
        <source>%1: statistics</source>
        <extracomment>%1 a section of the report, e.g. Points</extracomment>
        <translation>%1: статистика</translation>
    </message>
    <message>
        <source>%1: the %2 largest of %4 by |%3|</source>
        <extracomment>%1 a section (Points), %2 how many rows, %3 the column, %4 how many in all</extracomment>
        <translation>%1: %2 наибольших из %4 по |%3|</translation>
    </message>
    <message>
        <source>No warnings.</source>
        <translation>Предупреждений нет.</translation>
    </message>
    <message>
        <source>Error</source>
        <translation>Ошибка</translation>
    </message>
    <message>
        <source>Warning</source>
        <translation>Предупреждение</translation>
    </message>
    <message>
        <source>Note</source>
        <translation>Примечание</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <extracomment>%1 the severity (Error, Warning, Note), %2 the warning&apos;s title</extracomment>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>Warnings</source>
        <translation>Предупреждения</translation>
    </message>
    <message>
        <source>Out of tol.</source>
        <translation>Вне допуска</translation>
    </message>
    <message>
        <source>identified</source>
        <translation>определена</translation>
    </message>
    <message>
        <source>not identified</source>
        <translation>не определена</translation>
    </message>
</context>
<context>
    <name>UncertaintyBudget</name>
    <message>
        <source>Scan wait of the skip input</source>
        <translation>Ожидание опроса входа пропуска</translation>
    </message>
    <message>
        <source>Probe repeatability</source>
        <translation>Повторяемость датчика</translation>
    </message>
    <message>
        <source>Probe lobing</source>
        <translation>Лепестковость датчика</translation>
    </message>
    <message>
        <source>Calibration artefact</source>
        <translation>Эталон калибровки</translation>
    </message>
    <message>
        <source>Machine positioning repeatability</source>
        <translation>Повторяемость позиционирования станка</translation>
    </message>
    <message>
        <source>Thermal drift</source>
        <translation>Температурный дрейф</translation>
    </message>
    <message>
        <source>full range, ÷ √12</source>
        <translation>полный размах, ÷ √12</translation>
    </message>
    <message>
        <source>± half-width, ÷ √3</source>
        <translation>± полуширина, ÷ √3</translation>
    </message>
    <message>
        <source>2σ or k = 2, ÷ 2</source>
        <translation>2σ или k = 2, ÷ 2</translation>
    </message>
    <message>
        <source>%1, mean of %2</source>
        <extracomment>%1 how the value is stated, %2 the number of repeated touches averaged</extracomment>
        <translation>%1, среднее из %2</translation>
    </message>
    <message>
        <source>Term</source>
        <translation>Член бюджета</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Значение</translation>
    </message>
    <message>
        <source>Stated as</source>
        <translation>Как задан</translation>
    </message>
    <message>
        <source>Standard uncertainty</source>
        <translation>Стандартная неопределённость</translation>
    </message>
    <message>
        <source>Share</source>
        <translation>Доля</translation>
    </message>
    <message>
        <source>Combined (root sum of squares)</source>
        <translation>Суммарная (корень из суммы квадратов)</translation>
    </message>
    <message>
        <source>Expanded uncertainty, k = 2</source>
        <translation>Расширенная неопределённость, k = 2</translation>
    </message>
</context>
<context>
    <name>Warning</name>
    <message>
        <source>Overtravel near or over the limit</source>
        <translation>Перебег у предела или сверх него</translation>
    </message>
    <message>
        <source>Backoff too small</source>
        <translation>Слишком малый отвод</translation>
    </message>
    <message>
        <source>Backoff longer than needed</source>
        <translation>Отвод больше необходимого</translation>
    </message>
    <message>
        <source>Touch while accelerating</source>
        <translation>Касание во время разгона</translation>
    </message>
    <message>
        <source>Feedrate beyond the knee</source>
        <translation>Подача за точкой излома</translation>
    </message>
    <message>
        <source>Uncertainty over the target</source>
        <translation>Неопределённость выше цели</translation>
    </message>
    <message>
        <source>Calibration feed differs</source>
        <translation>Подача калибровки отличается</translation>
    </message>
    <message>
        <source>Overtravel %1 is %2 % of the probe&apos;s %3 limit: the probe or stylus will be damaged; lower the feed or the delays</source>
        <translation>Перебег %1 составляет %2 % от предела датчика %3: датчик или наконечник будет повреждён; уменьшите подачу или задержки</translation>
    </message>
    <message>
        <source>Overtravel %1 is %2 % of the probe&apos;s %3 limit: little margin left for the stylus</source>
        <translation>Перебег %1 составляет %2 % от предела датчика %3: запас для наконечника мал</translation>
    </message>
    <message>
        <source>Backoff %1 is more than the recommended %2 and wastes %3 per cycle</source>
        <translation>Отвод %1 больше рекомендуемого %2 и теряет %3 за цикл</translation>
    </message>
    <message>
        <source>Second touch starts closer than the distance needed to reach its feed: it triggers at %1 instead of %2, an error of %3 against a calibration at full feed</source>
        <translation>Второе касание начинается ближе, чем нужно для разгона до его подачи: срабатывание на %1 вместо %2, ошибка %3 относительно калибровки на полной подаче</translation>
    </message>
    <message>
        <source>First touch starts closer than the distance needed to reach its feed: it triggers at %1 instead of %2, an error of %3 against a calibration at full feed</source>
        <translation>Первое касание начинается ближе, чем нужно для разгона до его подачи: срабатывание на %1 вместо %2, ошибка %3 относительно калибровки на полной подаче</translation>
    </message>
    <message>
        <source>Probing feed %1 is beyond the knee at %2 and no faster: the cycle takes %3 longer, with more overtravel and uncertainty</source>
        <translation>Подача поиска %1 выше точки излома %2 и не быстрее: цикл длится на %3 дольше, с большим перебегом и неопределённостью</translation>
    </message>
    <message>
        <source>Uncertainty %1 exceeds the target %2</source>
        <translation>Неопределённость %1 превышает цель %2</translation>
    </message>
    <message>
        <source>Measuring at %1 but calibrated at %2: the delay travel shifts the measured value by %3; calibrate at the measuring feed</source>
        <translation>Измерение на %1, а калибровка на %2: путь за время задержки смещает измеренное значение на %3; откалибруйте на измерительной подаче</translation>
    </message>
    <message>
        <source>Probing feed %1 is beyond the knee at %2: the extra feed saves only %3 (under %4) while overtravel and uncertainty grow</source>
        <translation>Подача поиска %1 выше точки излома %2: прибавка подачи экономит лишь %3 (менее %4), а перебег и неопределённость растут</translation>
    </message>
    <message>
        <source>The fastest cycle lies at the highest feed searched, %1: the knee at %2 depends on that range; search faster feeds too</source>
        <translation>Самый быстрый цикл — на наибольшей из просмотренных подач, %1: точка излома %2 зависит от этого диапазона; проверьте и более высокие подачи</translation>
    </message>
    <message>
        <source>The fastest cycle lies at the lowest feed searched, %1: the knee at %2 depends on that range; search slower feeds too</source>
        <translation>Самый быстрый цикл — на наименьшей из просмотренных подач, %1: точка излома %2 зависит от этого диапазона; проверьте и более низкие подачи</translation>
    </message>
    <message>
        <source>Fastest cycle at the end of the range</source>
        <translation>Самый быстрый цикл на краю диапазона</translation>
    </message>
    <message>
        <source>Backoff %1 from the recorded trigger position is less than the recommended %2 (that position&apos;s distance past the surface plus room to reseat and to reach the measuring feed): the probe may not reseat before the second touch</source>
        <translation>Отвод %1 от записанной точки срабатывания меньше рекомендуемого %2 (расстояние этой точки за поверхностью плюс место для восстановления датчика и разгона до измерительной подачи): датчик может не восстановиться до второго касания</translation>
    </message>
    <message>
        <source>Backoff %1 from where the probe stopped is less than the recommended %2 (the first touch&apos;s overtravel plus room to reseat and to reach the measuring feed): the probe may not reseat before the second touch</source>
        <translation>Отвод %1 от точки остановки меньше рекомендуемого %2 (перебег первого касания плюс место для восстановления датчика и разгона до измерительной подачи): датчик может не восстановиться до второго касания</translation>
    </message>
    <message>
        <source>No probing feed from %1 to %2 gives a valid cycle: the overtravel reaches the probe&apos;s limit even at %1, so there is no knee; shorten the delays or use a probe with more overtravel</source>
        <translation>Ни одна подача поиска от %1 до %2 не даёт допустимого цикла: перебег достигает предела щупа уже при %1, поэтому излома нет; сократите задержки или возьмите щуп с бо́льшим допустимым перебегом</translation>
    </message>
    <message>
        <source>No valid feed</source>
        <translation>Нет допустимой подачи</translation>
    </message>
    <message>
        <source>Measuring feed %1 is over the probe&apos;s rated maximum %2: it may not trigger reliably or may be damaged; measure at %2 or slower</source>
        <translation>Измерительная подача %1 выше паспортного максимума щупа %2: щуп может срабатывать ненадёжно или повредиться; измеряйте на %2 или медленнее</translation>
    </message>
    <message>
        <source>Probing feed %1 is over the probe&apos;s rated maximum %2: it may not trigger reliably or may be damaged; probe at %2 or slower</source>
        <translation>Подача поиска %1 выше паспортного максимума щупа %2: щуп может срабатывать ненадёжно или повредиться; ищите на %2 или медленнее</translation>
    </message>
    <message>
        <source>Start distance %1 is inside the part&apos;s position uncertainty %2: where the part lies nearer, the probe starts in contact with it; start at least %3 out (the uncertainty plus the distance to reach the probing feed)</source>
        <translation>Расстояние подхода %1 лежит внутри неопределённости положения детали %2: если деталь ближе, щуп начинает в контакте с ней; начинайте не ближе %3 (неопределённость плюс путь разгона до подачи поиска)</translation>
    </message>
    <message>
        <source>Start distance %1 covers the part&apos;s position uncertainty %2 but not the distance to reach the probing feed after it: where the part lies nearer, the touch is made while accelerating; start at least %3 out</source>
        <translation>Расстояние подхода %1 покрывает неопределённость положения детали %2, но не путь разгона до подачи поиска после неё: если деталь ближе, касание происходит во время разгона; начинайте не ближе %3</translation>
    </message>
    <message>
        <source>Feed over the probe&apos;s rating</source>
        <translation>Подача выше паспорта щупа</translation>
    </message>
    <message>
        <source>Start within the part&apos;s position uncertainty</source>
        <translation>Начало в зоне неопределённости детали</translation>
    </message>
    <message>
        <source>The second touch&apos;s search ends %1 past where the first touch stopped, before its own stop %2 past the surface: it is braking when it touches, triggers below the measuring feed and stops at the search end; search at least %2 past the surface</source>
        <translation>Поиск второго касания заканчивается в %1 за точкой остановки первого касания, раньше его собственной остановки в %2 за поверхностью: касание происходит при торможении, срабатывание — ниже скорости измерительной подачи, остановка — в конце поиска; задайте поиск не менее %2 за поверхностью</translation>
    </message>
    <message>
        <source>The search ends %1 past the farthest place the surface can be, before the first touch&apos;s stop %2 past it: the axis is braking when it touches, triggers below the feed and stops at the search end; search at least %2 past the surface</source>
        <translation>Поиск заканчивается в %1 за самым дальним возможным положением поверхности, раньше остановки первого касания в %2 за ним: ось касается уже при торможении, срабатывает ниже подачи и останавливается в конце поиска; задайте поиск не менее %2 за поверхностью</translation>
    </message>
    <message>
        <source>Search ends before the stop</source>
        <translation>Поиск заканчивается до остановки</translation>
    </message>
    <message>
        <source>A protected move at the positioning feed %1 that meets an obstruction stops %2 past it, %3 % of the probe&apos;s %4 limit: the stylus would be overrun; lower the positioning feed</source>
        <translation>Защищённое перемещение на подаче позиционирования %1, встретив препятствие, останавливается в %2 за ним — %3 % от предела датчика %4: наконечник будет перегружен; снизьте подачу позиционирования</translation>
    </message>
    <message>
        <source>A protected move at the positioning feed %1 that meets an obstruction stops %2 past it, %3 % of the probe&apos;s %4 limit: little margin left for the stylus</source>
        <translation>Защищённое перемещение на подаче позиционирования %1, встретив препятствие, останавливается в %2 за ним — %3 % от предела датчика %4: запаса для наконечника почти нет</translation>
    </message>
    <message>
        <source>Protected moves near the overtravel limit</source>
        <translation>Защищённые перемещения у предела перебега</translation>
    </message>
    <message>
        <source>Overtravel %1 at %5 % feed override is %2 % of the probe&apos;s %3 limit: the probe or stylus will be damaged; lower the feed or the delays</source>
        <translation>Перебег %1 при коррекции подачи %5 % составляет %2 % от предела щупа %3: щуп или стилус будет повреждён; уменьшите подачу или задержки</translation>
    </message>
    <message>
        <source>Overtravel %1 at %5 % feed override is %2 % of the probe&apos;s %3 limit: little margin left for the stylus</source>
        <translation>Перебег %1 при коррекции подачи %5 % составляет %2 % от предела щупа %3: у стилуса остаётся мало запаса</translation>
    </message>
    <message>
        <source>A protected move at the positioning feed %1 and %5 % feed override that meets an obstruction stops %2 past it, %3 % of the probe&apos;s %4 limit: the stylus would be overrun; lower the positioning feed</source>
        <translation>Защищённое перемещение на подаче позиционирования %1 при коррекции подачи %5 %, встретив препятствие, останавливается на %2 за ним — %3 % от предела щупа %4: стилус будет перегружен; уменьшите подачу позиционирования</translation>
    </message>
    <message>
        <source>A protected move at the positioning feed %1 and %5 % feed override that meets an obstruction stops %2 past it, %3 % of the probe&apos;s %4 limit: little margin left for the stylus</source>
        <translation>Защищённое перемещение на подаче позиционирования %1 при коррекции подачи %5 %, встретив препятствие, останавливается на %2 за ним — %3 % от предела щупа %4: у стилуса остаётся мало запаса</translation>
    </message>
    <message>
        <source>No probing feed from %1 to %2 is reached: the first touch meets the surface before it reaches even %1, so there is no knee; start the touch farther out</source>
        <translation>Ни одна подача поиска от %1 до %2 не достигается: первое касание встречает поверхность, не достигнув даже %1, поэтому точки излома нет; начинайте касание дальше от поверхности</translation>
    </message>
</context>
<context>
    <name>probecycle::ui::CalibrationTab</name>
    <message>
        <source>Ring gauge: touches at 0° and 180°</source>
        <translation>Установочное кольцо: касания при 0° и 180°</translation>
    </message>
    <message>
        <source>Paste the trigger positions the control recorded, or import a CSV file. Columns &lt;code&gt;orientation_deg,x_mm,y_mm&lt;/code&gt;; spindle oriented at 0° and at 180°, 3 or more points each (typically X+, X−, Y+, Y−).</source>
        <translation>Вставьте положения срабатывания, записанные ЧПУ, или импортируйте файл CSV. Столбцы &lt;code&gt;orientation_deg,x_mm,y_mm&lt;/code&gt;; шпиндель ориентирован на 0° и на 180°, не менее 3 точек в каждой ориентации (обычно X+, X−, Y+, Y−).</translation>
    </message>
    <message>
        <source>(example)</source>
        <translation>(пример)</translation>
    </message>
    <message>
        <source>Gauge diameter</source>
        <translation>Диаметр кольца</translation>
    </message>
    <message>
        <source>The calibrated diameter of the ring gauge, from its certificate.</source>
        <translation>Аттестованный диаметр установочного кольца по его сертификату.</translation>
    </message>
    <message>
        <source>Runout limit</source>
        <translation>Предел биения</translation>
    </message>
    <message>
        <source>Warn when the stylus runout (eccentricity) is larger.</source>
        <translation>Предупреждать, если биение (эксцентриситет) наконечника больше.</translation>
    </message>
    <message>
        <source>Residual limit</source>
        <translation>Предел остатка</translation>
    </message>
    <message>
        <source>Warn when a point lies further than this off its fitted circle: dirt, a bad touch or a loose gauge.</source>
        <translation>Предупреждать, если точка лежит дальше этого от подобранной окружности: грязь, плохое касание или незакреплённое кольцо.</translation>
    </message>
    <message>
        <source>Length from a surface of known Z</source>
        <translation>Длина по поверхности с известной Z</translation>
    </message>
    <message>
        <source>Surface Z</source>
        <translation>Z поверхности</translation>
    </message>
    <message>
        <source>The known Z of the gauge top, sphere or block, set by a reference tool.</source>
        <translation>Известная Z верха кольца, сферы или плитки, заданная эталонным инструментом.</translation>
    </message>
    <message>
        <source>Trigger Z</source>
        <translation>Z срабатывания</translation>
    </message>
    <message>
        <source>The Z the control recorded at the touch; several touches separated by spaces or semicolons.</source>
        <translation>Z, записанная ЧПУ при касании; несколько касаний через пробел или точку с запятой.</translation>
    </message>
    <message>
        <source>Active length</source>
        <translation>Активная длина</translation>
    </message>
    <message>
        <source>The tool length offset active while probing (0 when none).</source>
        <translation>Коррекция длины инструмента, действующая при измерении (0, если нет).</translation>
    </message>
    <message>
        <source>Nominal length</source>
        <translation>Номинальная длина</translation>
    </message>
    <message>
        <source>The probe&apos;s nominal length, to express the result as wear (0 = none).</source>
        <translation>Номинальная длина датчика, чтобы выразить результат как износ (0 — нет).</translation>
    </message>
    <message>
        <source>none</source>
        <translation>нет</translation>
    </message>
    <message>
        <source>Radial deviations:</source>
        <translation>Радиальные отклонения:</translation>
    </message>
    <message>
        <source>Magnified, automatic</source>
        <translation>Увеличенные, автоматически</translation>
    </message>
    <message>
        <source>True scale</source>
        <translation>В натуральную величину</translation>
    </message>
    <message>
        <source>× %1</source>
        <extracomment>the magnification of the radial deviations in the ring plot</extracomment>
        <translation>× %1</translation>
    </message>
    <message>
        <source>X [%1]</source>
        <translation>X [%1]</translation>
    </message>
    <message>
        <source>Y [%1]</source>
        <translation>Y [%1]</translation>
    </message>
    <message>
        <source>Circle at 0°</source>
        <translation>Окружность при 0°</translation>
    </message>
    <message>
        <source>Circle at 180°</source>
        <translation>Окружность при 180°</translation>
    </message>
    <message>
        <source>Gauge centre</source>
        <translation>Центр кольца</translation>
    </message>
    <message>
        <source>Result</source>
        <translation>Результат</translation>
    </message>
    <message>
        <source>Stylus runout</source>
        <translation>Биение наконечника</translation>
    </message>
    <message>
        <source>Effective ball radius</source>
        <translation>Эффективный радиус шарика</translation>
    </message>
    <message>
        <source>Radius by direction</source>
        <translation>Радиус по направлениям</translation>
    </message>
    <message>
        <source>Largest residual</source>
        <translation>Наибольший остаток</translation>
    </message>
    <message>
        <source>Points</source>
        <translation>Точки</translation>
    </message>
    <message>
        <source>Warnings</source>
        <translation>Предупреждения</translation>
    </message>
    <message>
        <source>No warnings.</source>
        <translation>Предупреждений нет.</translation>
    </message>
    <message>
        <source>Export CSV report…</source>
        <translation>Экспорт отчёта CSV…</translation>
    </message>
    <message>
        <source>X %1</source>
        <translation>X %1</translation>
    </message>
    <message>
        <source>Y %1</source>
        <translation>Y %1</translation>
    </message>
    <message>
        <source>unknown: one orientation only</source>
        <translation>неизвестно: только одна ориентация</translation>
    </message>
    <message>
        <source>centre %1, %2; radius %3</source>
        <translation>центр %1, %2; радиус %3</translation>
    </message>
    <message>
        <source>no points</source>
        <translation>нет точек</translation>
    </message>
    <message>
        <source>%1 at 0°, %2 at 180°; gauge %3</source>
        <translation>%1 при 0°, %2 при 180°; кольцо %3</translation>
    </message>
    <message>
        <source>Radial deviations magnified × %1</source>
        <translation>Радиальные отклонения увеличены × %1</translation>
    </message>
    <message>
        <source>No fit yet</source>
        <translation>Подбора ещё нет</translation>
    </message>
    <message>
        <source>Trigger Z: “%1” is not a number.</source>
        <translation>Z срабатывания: «%1» — не число.</translation>
    </message>
    <message>
        <source>Effective length: &lt;b&gt;%1&lt;/b&gt;</source>
        <translation>Эффективная длина: &lt;b&gt;%1&lt;/b&gt;</translation>
    </message>
    <message>
        <source>Wear: %1</source>
        <translation>Износ: %1</translation>
    </message>
    <message>
        <source>Enter the trigger Z of one or more touches.</source>
        <translation>Введите Z срабатывания одного или нескольких касаний.</translation>
    </message>
    <message>
        <source>Nothing to export: fit the ring points or enter a length first.</source>
        <translation>Нечего экспортировать: сначала подберите точки кольца или введите длину.</translation>
    </message>
    <message>
        <source>Import ring gauge points</source>
        <translation>Импорт точек установочного кольца</translation>
    </message>
    <message>
        <source>Export calibration report</source>
        <translation>Экспорт отчёта о калибровке</translation>
    </message>
    <message>
        <source>Spindle at 0°</source>
        <translation>Шпиндель на 0°</translation>
    </message>
    <message>
        <source>Spindle at 180°</source>
        <translation>Шпиндель на 180°</translation>
    </message>
    <message>
        <source>%1 in all</source>
        <translation>всего %1</translation>
    </message>
    <message>
        <source>Touches: %1, spread %2</source>
        <translation>Касаний: %1, разброс %2</translation>
    </message>
    <message>
        <source>The ring-gauge calibration as a program for your control (LinuxCNC, grbl, Fanuc, Haas, Mitsubishi, Siemens), with the plan that the import of its log needs.</source>
        <translation>Калибровка по установочному кольцу как программа для вашей ЧПУ (LinuxCNC, grbl, Fanuc, Haas, Mitsubishi, Siemens) вместе с планом, который нужен для импорта её журнала.</translation>
    </message>
    <message>
        <source>What the control recorded while it ran the program, read with the program&apos;s plan into the points and fitted.</source>
        <translation>То, что ЧПУ записала при выполнении программы: читается вместе с планом программы в точки и подбирается.</translation>
    </message>
    <message>
        <source>e.g. %1; %2</source>
        <translation>напр. %1; %2</translation>
    </message>
</context>
<context>
    <name>probecycle::ui::ComparisonTab</name>
    <message>
        <source>Files and setup</source>
        <translation>Файлы и настройка</translation>
    </message>
    <message>
        <source>CSV files with a header row, in the plan&apos;s order: the plan &lt;code&gt;x_mm,y_mm,z_mm,i,j,k&lt;/code&gt; (outward unit normal), points &lt;code&gt;x_mm,y_mm,z_mm&lt;/code&gt; (or DMIS &lt;code&gt;PTMEAS/CART&lt;/code&gt;), the block &lt;code&gt;face,x_mm,y_mm,z_mm&lt;/code&gt; with faces A, B, C.</source>
        <translation>Файлы CSV со строкой заголовка, в порядке плана: план — &lt;code&gt;x_mm,y_mm,z_mm,i,j,k&lt;/code&gt; (внешняя единичная нормаль), точки — &lt;code&gt;x_mm,y_mm,z_mm&lt;/code&gt; (или DMIS &lt;code&gt;PTMEAS/CART&lt;/code&gt;), блок — &lt;code&gt;face,x_mm,y_mm,z_mm&lt;/code&gt; с гранями A, B, C.</translation>
    </message>
    <message>
        <source>Inspection plan</source>
        <translation>План контроля</translation>
    </message>
    <message>
        <source>Reference part, CMM points</source>
        <translation>Эталонная деталь, точки КИМ</translation>
    </message>
    <message>
        <source>Test part, on-machine points at C = 0</source>
        <translation>Контролируемая деталь, точки измерения на станке при C = 0</translation>
    </message>
    <message>
        <source>Reference part, on-machine points after the turn</source>
        <translation>Эталонная деталь, точки измерения на станке после поворота</translation>
    </message>
    <message>
        <source>Block at C = 0 (optional)</source>
        <translation>Блок при C = 0 (необязательно)</translation>
    </message>
    <message>
        <source>Block after the turn (optional)</source>
        <translation>Блок после поворота (необязательно)</translation>
    </message>
    <message>
        <source>Nominal points and outward unit normals (the side the probe comes from), in machine coordinates at the measuring position (C = 0).</source>
        <translation>Номинальные точки и внешние единичные нормали (со стороны подвода датчика) в координатах станка в положении измерения (C = 0).</translation>
    </message>
    <message>
        <source>The reference part as the CMM measured it, one point per plan point, in the plan&apos;s coordinates.</source>
        <translation>Эталонная деталь, как её измерила КИМ: по одной точке на каждую точку плана, в координатах плана.</translation>
    </message>
    <message>
        <source>The test part probed on the machine along the plan, C at 0.</source>
        <translation>Контролируемая деталь, измеренная на станке по плану, ось C в положении 0.</translation>
    </message>
    <message>
        <source>The reference part probed along the same plan after C turned by the angle: at the same place of the machine as the test part.</source>
        <translation>Эталонная деталь, измеренная по тому же плану после поворота оси C на угол сравнения: в том же месте станка, где была контролируемая деталь.</translation>
    </message>
    <message>
        <source>Three faces of a block&apos;s corner, touched at C = 0: they give the C axis&apos;s six errors. Without the block the C axis is taken as exact.</source>
        <translation>Три грани угла блока, измеренные касаниями при C = 0: по ним определяются шесть погрешностей оси C. Без блока ось C считается точной.</translation>
    </message>
    <message>
        <source>The same three faces touched after the turn.</source>
        <translation>Те же три грани, измеренные касаниями после поворота.</translation>
    </message>
    <message>
        <source>Choose a file…</source>
        <translation>Выбрать файл…</translation>
    </message>
    <message>
        <source>C axis X</source>
        <translation>Ось C, X</translation>
    </message>
    <message>
        <source>Where the C axis is, in machine X.</source>
        <translation>Положение оси C по координате X станка.</translation>
    </message>
    <message>
        <source>C axis Y</source>
        <translation>Ось C, Y</translation>
    </message>
    <message>
        <source>Where the C axis is, in machine Y.</source>
        <translation>Положение оси C по координате Y станка.</translation>
    </message>
    <message>
        <source>Comparison angle</source>
        <translation>Угол сравнения</translation>
    </message>
    <message>
        <source>How far C turns between the two measurements (180° for parts clamped opposite each other).</source>
        <translation>Угол поворота оси C между двумя измерениями (180° для деталей, закреплённых друг напротив друга).</translation>
    </message>
    <message>
        <source>Tolerance (±)</source>
        <translation>Допуск (±)</translation>
    </message>
    <message>
        <source>Half-width of the tolerance band about the nominal surface.</source>
        <translation>Половина ширины поля допуска относительно номинальной поверхности.</translation>
    </message>
    <message>
        <source>Run</source>
        <translation>Выполнить</translation>
    </message>
    <message>
        <source>Simulate example data</source>
        <translation>Смоделировать пример данных</translation>
    </message>
    <message>
        <source>Write a simulated data set with a known truth (truth.csv) to a folder and run it.</source>
        <translation>Записать в папку смоделированный набор данных с известными истинными значениями (truth.csv) и выполнить по нему расчёт.</translation>
    </message>
    <message>
        <source>Open project…</source>
        <translation>Открыть проект…</translation>
    </message>
    <message>
        <source>Save project…</source>
        <translation>Сохранить проект…</translation>
    </message>
    <message>
        <source>Deviation of the test part</source>
        <translation>Отклонение детали</translation>
    </message>
    <message>
        <source>X [%1]</source>
        <translation>X [%1]</translation>
    </message>
    <message>
        <source>Y [%1]</source>
        <translation>Y [%1]</translation>
    </message>
    <message>
        <source>Deviations: direct OMM and comparison</source>
        <translation>Отклонения: прямое измерение на станке и сравнение</translation>
    </message>
    <message>
        <source>Deviation [%1]</source>
        <translation>Отклонение [%1]</translation>
    </message>
    <message>
        <source>Points</source>
        <translation>Точки</translation>
    </message>
    <message>
        <source>Direct OMM</source>
        <translation>Прямое изм. на станке</translation>
    </message>
    <message>
        <source>Comparison</source>
        <translation>Сравнение</translation>
    </message>
    <message>
        <source>Tolerance</source>
        <translation>Допуск</translation>
    </message>
    <message>
        <source>Result</source>
        <translation>Результат</translation>
    </message>
    <message>
        <source>C-axis errors</source>
        <translation>Погрешности оси C</translation>
    </message>
    <message>
        <source>Error</source>
        <translation>Погрешность</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Значение</translation>
    </message>
    <message>
        <source>Uncertainty</source>
        <translation>Неопределённость</translation>
    </message>
    <message>
        <source>Min</source>
        <translation>Мин.</translation>
    </message>
    <message>
        <source>Max</source>
        <translation>Макс.</translation>
    </message>
    <message>
        <source>RMS</source>
        <translation>СКЗ</translation>
    </message>
    <message>
        <source>Out of tol.</source>
        <translation>Вне допуска</translation>
    </message>
    <message>
        <source>Warnings</source>
        <translation>Предупреждения</translation>
    </message>
    <message>
        <source>No warnings.</source>
        <translation>Предупреждений нет.</translation>
    </message>
    <message>
        <source>Points, worst first</source>
        <translation>Точки, худшие первыми</translation>
    </message>
    <message>
        <source>Point</source>
        <translation>Точка</translation>
    </message>
    <message>
        <source>X</source>
        <translation>X</translation>
    </message>
    <message>
        <source>Y</source>
        <translation>Y</translation>
    </message>
    <message>
        <source>Z</source>
        <translation>Z</translation>
    </message>
    <message>
        <source>Deviation</source>
        <translation>Отклонение</translation>
    </message>
    <message>
        <source>System error</source>
        <translation>Систем. погрешность</translation>
    </message>
    <message>
        <source>Export report…</source>
        <translation>Экспорт отчёта…</translation>
    </message>
    <message>
        <source>The block is needed at both angles: choose both block files, or neither.</source>
        <translation>Блок нужен при обоих углах: выберите оба файла блока или ни одного.</translation>
    </message>
    <message>
        <source>Cannot make the folder %1.</source>
        <translation>Не удалось создать папку %1.</translation>
    </message>
    <message>
        <source>Nothing to export: run the comparison first.</source>
        <translation>Нечего экспортировать: сначала выполните сравнение.</translation>
    </message>
    <message>
        <source>εx (EAC)</source>
        <translation>εx (EAC)</translation>
    </message>
    <message>
        <source>εy (EBC)</source>
        <translation>εy (EBC)</translation>
    </message>
    <message>
        <source>εz (ECC)</source>
        <translation>εz (ECC)</translation>
    </message>
    <message>
        <source>δx (EXC)</source>
        <translation>δx (EXC)</translation>
    </message>
    <message>
        <source>δy (EYC)</source>
        <translation>δy (EYC)</translation>
    </message>
    <message>
        <source>δz (EZC)</source>
        <translation>δz (EZC)</translation>
    </message>
    <message>
        <source>µrad</source>
        <translation>мкрад</translation>
    </message>
    <message>
        <source>not identified</source>
        <translation>не определено</translation>
    </message>
    <message>
        <source>unknown</source>
        <translation>неизвестно</translation>
    </message>
    <message>
        <source>below %1 %2 (out)</source>
        <translation>ниже %1 %2 (вне доп.)</translation>
    </message>
    <message>
        <source>above +%1 %2 (out)</source>
        <translation>выше +%1 %2 (вне доп.)</translation>
    </message>
    <message>
        <source>%1 to %2 %3</source>
        <translation>от %1 до %2 %3</translation>
    </message>
    <message>
        <source>Point files (*.csv *.dmi *.dmis *.txt);;All files (*)</source>
        <translation>Файлы точек (*.csv *.dmi *.dmis *.txt);;Все файлы (*)</translation>
    </message>
    <message>
        <source>Open comparison project</source>
        <translation>Открыть проект сравнения</translation>
    </message>
    <message>
        <source>Comparison projects (*.json)</source>
        <translation>Проекты сравнения (*.json)</translation>
    </message>
    <message>
        <source>Save comparison project</source>
        <translation>Сохранить проект сравнения</translation>
    </message>
    <message>
        <source>Export comparison report</source>
        <translation>Экспорт отчёта о сравнении</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>Файлы CSV (*.csv)</translation>
    </message>
    <message>
        <source>Choose a file for “%1”.</source>
        <translation>Выберите файл для «%1».</translation>
    </message>
    <message>
        <source>Direct OMM against the comparison [%1]</source>
        <translation>Прямое измерение на станке в сопоставлении со сравнением [%1]</translation>
    </message>
</context>
<context>
    <name>probecycle::ui::CompensationPanel</name>
    <message>
        <source>Uncompensated</source>
        <translation>Без компенсации</translation>
    </message>
    <message>
        <source>Naive v·τ</source>
        <translation>Простая v·τ</translation>
    </message>
    <message>
        <source>Cycle lag (real increments)</source>
        <translation>Реальные приращения</translation>
    </message>
    <message>
        <source>Timestamp interpolation</source>
        <translation>По метке времени</translation>
    </message>
    <message>
        <source>Real increments</source>
        <translation>Приращения</translation>
    </message>
    <message>
        <source>Timestamp</source>
        <translation>Метка времени</translation>
    </message>
    <message>
        <source>Feed</source>
        <translation>Подача</translation>
    </message>
    <message>
        <source>Interpolation period</source>
        <translation>Период интерполяции</translation>
    </message>
    <message>
        <source>Lag</source>
        <translation>Запаздывание</translation>
    </message>
    <message>
        <source>Speed at the trigger</source>
        <translation>Скорость при срабатывании</translation>
    </message>
    <message>
        <source>Direction of travel</source>
        <translation>Направление движения</translation>
    </message>
    <message>
        <source>Trigger phase in its cycle</source>
        <translation>Фаза срабатывания в периоде</translation>
    </message>
    <message>
        <source>Encoder counts per mm</source>
        <translation>Импульсов энкодера на мм</translation>
    </message>
    <message>
        <source>Encoder counter width</source>
        <translation>Разрядность счётчика энкодера</translation>
    </message>
    <message>
        <source>Delay for v·τ</source>
        <translation>Задержка для v·τ</translation>
    </message>
    <message>
        <source>Compensation of the trigger position</source>
        <translation>Компенсация положения срабатывания</translation>
    </message>
    <message>
        <source>The programmed probing feed.</source>
        <translation>Запрограммированная подача поиска.</translation>
    </message>
    <message>
        <source>The control&apos;s interpolation cycle.</source>
        <translation>Период интерполяции ЧПУ.</translation>
    </message>
    <message>
        <source>Cycles between the end of the trigger&apos;s cycle and the recorded position; the delay-stability test above measures it.</source>
        <translation>Число периодов между концом периода срабатывания и записанным положением; его измеряет испытание стабильности задержки выше.</translation>
    </message>
    <message>
        <source> cycles</source>
        <translation> периодов</translation>
    </message>
    <message>
        <source>Touch</source>
        <translation>Касание</translation>
    </message>
    <message>
        <source>At constant speed, or while the axis is braking.</source>
        <translation>На постоянной скорости или во время торможения оси.</translation>
    </message>
    <message>
        <source>At constant speed</source>
        <translation>Постоянная скорость</translation>
    </message>
    <message>
        <source>While braking</source>
        <translation>При торможении</translation>
    </message>
    <message>
        <source>While braking: the speed at the trigger, in % of the feed.</source>
        <translation>Во время торможения: скорость при срабатывании в % от подачи.</translation>
    </message>
    <message>
        <source>Take period and lag from the fit</source>
        <translation>Период и запаздывание из подбора</translation>
    </message>
    <message>
        <source>Machine dynamics from the scenario. While braking, v·τ assumes the feed through the whole delay and over-corrects; the real increments of the last cycles stay within one cycle&apos;s travel.</source>
        <translation>Динамика станка — из сценария. При торможении v·τ считает подачу постоянной всю задержку и перекорректирует; реальные приращения последних периодов дают ошибку в пределах пути за один период.</translation>
    </message>
    <message>
        <source>Error of the corrected position while braking</source>
        <translation>Ошибка исправленного положения при торможении</translation>
    </message>
    <message>
        <source>Speed at the trigger [% of the feed]</source>
        <translation>Скорость при срабатывании [% от подачи]</translation>
    </message>
    <message>
        <source>Error [%1]</source>
        <translation>Ошибка [%1]</translation>
    </message>
    <message>
        <source>Method</source>
        <translation>Метод</translation>
    </message>
    <message>
        <source>Position [%1]</source>
        <translation>Положение [%1]</translation>
    </message>
    <message>
        <source>Trigger at %1 mm/s, recorded %2 cycles later at %3 mm/s; v·τ uses τ = %4.</source>
        <extracomment>%1 speed at the trigger, %2 lag in cycles, %3 speed then, %4 the delay v·τ uses</extracomment>
        <translation>Срабатывание на %1 мм/с, запись через %2 периодов на %3 мм/с; v·τ использует τ = %4.</translation>
    </message>
    <message>
        <source>Counter roll-overs: %1.</source>
        <translation>Переполнений счётчика: %1.</translation>
    </message>
    <message>
        <source>Compensated lag</source>
        <translation>Компенсация</translation>
    </message>
    <message>
        <source>The lag the real-increments method subtracts. Controls are often set up with a lag other than the machine&apos;s (a published study compensated 7 to 9 cycles on a machine that lagged about 10): each cycle too few leaves one cycle&apos;s travel of error. Lowest value: the lag itself.</source>
        <translation>Запаздывание, которое вычитает метод приращений. ЧПУ часто настроены на запаздывание, отличное от фактического (в опубликованном исследовании компенсировали 7–9 периодов на станке с запаздыванием около 10): каждый недостающий период оставляет ошибку в путь за один период. Наименьшее значение: само запаздывание.</translation>
    </message>
    <message>
        <source>as the lag</source>
        <translation>= запаздыванию</translation>
    </message>
    <message>
        <source>Real increments: error against the compensated lag</source>
        <translation>Приращения: ошибка в зависимости от компенсируемого запаздывания</translation>
    </message>
    <message>
        <source>Compensated lag [cycles]</source>
        <translation>Компенсируемое запаздывание [периодов]</translation>
    </message>
    <message>
        <source>Dashed: the machine&apos;s lag. Dotted: the lag compensated. The error grows by one cycle&apos;s travel for each cycle the compensation is off.</source>
        <translation>Штриховая линия: запаздывание станка. Пунктир: компенсируемое запаздывание. Ошибка растёт на путь за один период с каждым периодом расхождения.</translation>
    </message>
    <message>
        <source>Against the compensated lag</source>
        <translation>От компенсируемого запаздывания</translation>
    </message>
</context>
<context>
    <name>probecycle::ui::CycleCharts</name>
    <message>
        <source>Probing feedrate [%1]</source>
        <translation>Подача поиска [%1]</translation>
    </message>
    <message>
        <source>Cycle time vs probing feedrate</source>
        <translation>Время цикла в зависимости от подачи поиска</translation>
    </message>
    <message>
        <source>Cycle time [%1]</source>
        <translation>Время цикла [%1]</translation>
    </message>
    <message>
        <source>Single-touch</source>
        <translation>Однократное</translation>
    </message>
    <message>
        <source>Knee</source>
        <translation>Излом</translation>
    </message>
    <message>
        <source>Time [%1]</source>
        <translation>Время [%1]</translation>
    </message>
    <message>
        <source>Overtravel and uncertainty vs feedrate</source>
        <translation>Перебег и неопределённость в зависимости от подачи</translation>
    </message>
    <message>
        <source>Overtravel [%1]</source>
        <translation>Перебег [%1]</translation>
    </message>
    <message>
        <source>Uncertainty, k = 2 [%1]</source>
        <translation>Неопредел., k = 2 [%1]</translation>
    </message>
    <message>
        <source>Overtravel</source>
        <translation>Перебег</translation>
    </message>
    <message>
        <source>Limit</source>
        <translation>Предел</translation>
    </message>
    <message>
        <source>Target</source>
        <translation>Цель</translation>
    </message>
    <message>
        <source>Position and speed through the cycle</source>
        <translation>Положение и скорость в течение цикла</translation>
    </message>
    <message>
        <source>Position [%1]</source>
        <translation>Положение [%1]</translation>
    </message>
    <message>
        <source>Speed [%1]</source>
        <translation>Скорость [%1]</translation>
    </message>
    <message>
        <source>Position</source>
        <translation>Положение</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Скорость</translation>
    </message>
    <message>
        <source>Surface</source>
        <translation>Поверхность</translation>
    </message>
    <message>
        <source>Baseline (dashed)</source>
        <translation>База (штрих)</translation>
    </message>
    <message>
        <source>Phases: total %1</source>
        <translation>Фазы: всего %1</translation>
    </message>
    <message>
        <source>Phases</source>
        <translation>Фазы</translation>
    </message>
    <message>
        <source>Uncertainty</source>
        <translation>Неопределённость</translation>
    </message>
    <message>
        <source>Two-touch, best backoff</source>
        <translation>Двукратное, лучший отвод</translation>
    </message>
    <message>
        <source>This cycle</source>
        <translation>Этот цикл</translation>
    </message>
    <message>
        <source>1st touch</source>
        <translation>1-е касание</translation>
    </message>
    <message>
        <source>2nd touch</source>
        <translation>2-е касание</translation>
    </message>
    <message>
        <source>This cycle (invalid)</source>
        <translation>Этот цикл (недоп.)</translation>
    </message>
    <message>
        <source>Invalid</source>
        <translation>Недопустимые</translation>
    </message>
    <message>
        <source>The phases of the current cycle in time order, each row with its total time over all touches. Grey: the cycle is invalid and cannot run as set (the title and the warnings say why); its phases are what the model computes.</source>
        <translation>Фазы текущего цикла в порядке времени; в каждой строке — суммарное время фазы по всем касаниям. Серым: цикл недопустим и не может выполняться с заданными параметрами (причину называют заголовок и предупреждения); фазы показаны такими, какими их рассчитывает модель.</translation>
    </message>
    <message>
        <source>Phases of an invalid cycle (grey): %1</source>
        <extracomment>%1: why the cycle cannot run, e.g. &quot;Backoff too small&quot;</extracomment>
        <translation>Фазы недопустимого цикла (серые): %1</translation>
    </message>
    <message>
        <source>1st touch at %1 % override</source>
        <translation>1-е касание при коррекции %1 %</translation>
    </message>
    <message>
        <source>Overtravel at %1 % override</source>
        <translation>Перебег при коррекции %1 %</translation>
    </message>
    <message>
        <source>2nd touch at %1 % override</source>
        <translation>2-е касание при коррекции %1 %</translation>
    </message>
    <message>
        <source>This cycle&apos;s uncertainty</source>
        <translation>Неопределённость цикла</translation>
    </message>
    <message>
        <source>Red: overtravel of a touch at each feed, at the highest feed override, against the probe&apos;s limit (dashed); the shaded feeds overtravel beyond it. Two-touch: the first touch solid, the second dotted; with a fixed backoff a fast first touch leaves the second too little room to brake, so the second may overtravel more. Blue, right axis: the uncertainty (k = 2) of a touch measured at each feed against the target (dotted); the dot is this cycle&apos;s, the readout&apos;s figure, at the feed of the touch that measures. Vertical lines: the probing feed and, for two-touch, the measuring feed (blue, dotted).</source>
        <translation>Красный: перебег касания при каждой подаче при наибольшей коррекции подачи относительно предела щупа (пунктир); на заштрихованных подачах перебег выходит за него. Двойное касание: первое касание — сплошная линия, второе — точечная; при фиксированном отводе быстрое первое касание оставляет второму слишком мало места для торможения, поэтому второе может перебегать больше. Синий, правая ось: неопределённость (k = 2) касания, измеренного при каждой подаче, относительно цели (точечная линия); точка — неопределённость этого цикла, значение индикатора, при подаче измеряющего касания. Вертикальные линии: подача зондирования и, для двойного касания, измерительная подача (синяя, точечная).</translation>
    </message>
    <message>
        <source>Measuring feedrate</source>
        <translation>Измерительная подача</translation>
    </message>
    <message>
        <source>Single-touch, feed not reached</source>
        <translation>Однократное, подача не достигнута</translation>
    </message>
    <message>
        <source>Two-touch, feed not reached</source>
        <translation>Двукратное, подача не достигнута</translation>
    </message>
    <message>
        <source>Cycle time of the whole cycle against the probing feed, for single-touch and two-touch with everything else as set. Vertical line: the current feed. Dot: the knee, the lowest valid feed within the knee tolerance of the best time. Grey, dashed: feeds whose cycle is invalid (overtravel over the limit, backoff too small). Dotted: feeds the first touch never reaches from its start, so the cycle is not at the feed it says (its time falls only because of that); the knee is not among them. A red dashed line: this cycle is invalid and has no cycle time (see the warnings).</source>
        <translation>Время всего цикла в зависимости от подачи поиска для однократного и двукратного касания при прочих заданных параметрах. Вертикальная линия — текущая подача. Точка — точка излома: наименьшая допустимая подача, время цикла на которой хуже лучшего не более чем на допуск точки излома. Серый пунктир: подачи, при которых цикл недопустим (перебег сверх предела, слишком малый отвод). Точечная линия: подачи, которых первое касание не достигает от своего начала, так что цикл идёт не на заявленной подаче (его время падает только поэтому); точка излома среди них не ищется. Красная пунктирная линия: этот цикл недопустим и времени цикла не имеет (см. предупреждения).</translation>
    </message>
    <message>
        <source>Position along the probing direction of each touch (the surface is dashed) and path speed through the whole cycle. The position line breaks during the moves between touches, which run across that direction; the speed shows them.</source>
        <translation>Положение вдоль направления измерения для каждого касания (поверхность — штрих) и скорость по траектории в течение всего цикла. Во время перемещений между касаниями, идущих поперёк этого направления, линия положения прерывается; их показывает скорость.</translation>
    </message>
</context>
<context>
    <name>probecycle::ui::DelayFitPanel</name>
    <message>
        <source>Delay from touches at several feeds (delay-stability test)</source>
        <translation>Задержка по касаниям на нескольких подачах (испытание стабильности задержки)</translation>
    </message>
    <message>
        <source>Touch the same surface several times at each of several feeds, per axis and direction, starting far enough out to be at full speed. Paste or import the positions: &lt;code&gt;axis,direction,feed_mm_min,measured_mm&lt;/code&gt; (direction +1 or −1, of travel).</source>
        <translation>Коснитесь одной и той же поверхности несколько раз на каждой из нескольких подач, по каждой оси и направлению, начиная достаточно далеко для полной скорости. Вставьте или импортируйте положения: &lt;code&gt;axis,direction,feed_mm_min,measured_mm&lt;/code&gt; (direction — направление движения, +1 или −1).</translation>
    </message>
    <message>
        <source>(example)</source>
        <translation>(пример)</translation>
    </message>
    <message>
        <source>Interpolation period</source>
        <translation>Период интерполяции</translation>
    </message>
    <message>
        <source>The control&apos;s interpolation cycle, to express the delay in cycles (optional).</source>
        <translation>Период интерполяции ЧПУ, чтобы выразить задержку в периодах (необязательно).</translation>
    </message>
    <message>
        <source>none</source>
        <translation>нет</translation>
    </message>
    <message>
        <source>Measured minus zero-speed position, against feed</source>
        <translation>Отклонение от положения при нулевой скорости</translation>
    </message>
    <message>
        <source>Feed [%1]</source>
        <translation>Подача [%1]</translation>
    </message>
    <message>
        <source>Deviation [%1]</source>
        <translation>Отклонение [%1]</translation>
    </message>
    <message>
        <source>Group / feed</source>
        <translation>Группа/подача</translation>
    </message>
    <message>
        <source>Delay τ</source>
        <translation>Задержка τ</translation>
    </message>
    <message>
        <source>Cycles</source>
        <translation>Периоды</translation>
    </message>
    <message>
        <source>p₀ / mean</source>
        <translation>p₀/среднее</translation>
    </message>
    <message>
        <source>2σ / range</source>
        <translation>2σ/размах</translation>
    </message>
    <message>
        <source>n</source>
        <translation>n</translation>
    </message>
    <message>
        <source>The total delay: the slope of the line over the feeds.</source>
        <translation>Полная задержка: наклон прямой по подачам.</translation>
    </message>
    <message>
        <source>The delay in interpolation cycles (with the period given).</source>
        <translation>Задержка в периодах интерполяции (если период задан).</translation>
    </message>
    <message>
        <source>Group: the zero-speed position p₀. Feed: the mean deviation from p₀.</source>
        <translation>Группа: положение при нулевой скорости p₀. Подача: среднее отклонение от p₀.</translation>
    </message>
    <message>
        <source>Group: twice the standard deviation of the residuals of the line. Feed: the range (max − min) of its touches, the delay&apos;s stability.</source>
        <translation>Группа: удвоенное СКО остатков прямой. Подача: размах (макс − мин) её касаний — стабильность задержки.</translation>
    </message>
    <message>
        <source>Touches</source>
        <translation>Касания</translation>
    </message>
    <message>
        <source>Warnings</source>
        <translation>Предупреждения</translation>
    </message>
    <message>
        <source>No warnings.</source>
        <translation>Предупреждений нет.</translation>
    </message>
    <message>
        <source>Delay to apply:</source>
        <translation>Применить задержку:</translation>
    </message>
    <message>
        <source>Apply to scenario</source>
        <translation>Применить к сценарию</translation>
    </message>
    <message>
        <source>Longest delay (safe side)</source>
        <translation>Наибольшая задержка (с запасом)</translation>
    </message>
    <message>
        <source>%1: τ = %2</source>
        <translation>%1: τ = %2</translation>
    </message>
    <message>
        <source>Import touches</source>
        <translation>Импорт касаний</translation>
    </message>
    <message>
        <source>Fit the touches first.</source>
        <translation>Сначала подберите касания.</translation>
    </message>
    <message>
        <source>No scenario to apply the delay to.</source>
        <translation>Нет сценария, к которому применить задержку.</translation>
    </message>
    <message>
        <source>Controller latency = %1 delay %2 − interface %3 − half scan %4 = &lt;b&gt;%5&lt;/b&gt; (now %6)</source>
        <extracomment>%1 group, %2 its delay, %3 interface delay, %4 half scan period, %5 result, %6 now</extracomment>
        <translation>Задержка ЧПУ = %1 задержка %2 − интерфейс %3 − половина опроса %4 = &lt;b&gt;%5&lt;/b&gt; (сейчас %6)</translation>
    </message>
    <message>
        <source>Sets machine.controller_latency_s to the fitted delay less the probe&apos;s interface delay and half the scan period. With a latched input the fitted delay is the interface delay: it sets probe.interface_delay_s and leaves the latency alone.</source>
        <translation>Задаёт machine.controller_latency_s: подобранная задержка минус задержка интерфейса датчика и половина периода опроса. При входе с защёлкой подобранная задержка — это задержка интерфейса: задаётся probe.interface_delay_s, а задержка ЧПУ не меняется.</translation>
    </message>
    <message>
        <source>Latched input: interface delay = %1 delay &lt;b&gt;%2&lt;/b&gt; (now %3); the controller latency is left as it is</source>
        <extracomment>%1 group, %2 its delay (the result), %3 the interface delay now</extracomment>
        <translation>Вход с защёлкой: задержка интерфейса = %1 задержка &lt;b&gt;%2&lt;/b&gt; (сейчас %3); задержка ЧПУ не меняется</translation>
    </message>
    <message>
        <source>Export CSV report…</source>
        <translation>Экспорт отчёта CSV…</translation>
    </message>
    <message>
        <source>The delay per group, its stability per feed, every touch&apos;s residual and the warnings as CSV: the same file as probecycle-cli latency fit --report.</source>
        <translation>Задержка по группам, её стабильность по подачам, остаток каждого касания и предупреждения в CSV: тот же файл, что probecycle-cli latency fit --report.</translation>
    </message>
    <message>
        <source>Nothing to export: fit the touches first.</source>
        <translation>Нечего экспортировать: сначала выполните подгонку по касаниям.</translation>
    </message>
    <message>
        <source>Export delay fit report</source>
        <translation>Экспорт отчёта о задержке</translation>
    </message>
    <message>
        <source>The delay-stability test as a program for your control (LinuxCNC, grbl, Fanuc, Haas, Mitsubishi, Siemens), with the plan that the import of its log needs.</source>
        <translation>Испытание стабильности задержки как программа для вашей ЧПУ (LinuxCNC, grbl, Fanuc, Haas, Mitsubishi, Siemens) вместе с планом, который нужен для импорта её журнала.</translation>
    </message>
    <message>
        <source>What the control recorded while it ran the program, read with the program&apos;s plan into the touches and fitted.</source>
        <translation>То, что ЧПУ записала при выполнении программы: читается вместе с планом программы в касания и подбирается.</translation>
    </message>
</context>
<context>
    <name>probecycle::ui::Document</name>
    <message>
        <source>Untitled</source>
        <translation>Без имени</translation>
    </message>
</context>
<context>
    <name>probecycle::ui::FitInput</name>
    <message>
        <source>Import CSV…</source>
        <translation>Импорт CSV…</translation>
    </message>
    <message>
        <source>Fit</source>
        <translation>Подобрать</translation>
    </message>
    <message>
        <source>Program…</source>
        <translation>Программа…</translation>
    </message>
    <message>
        <source>Import machine log…</source>
        <translation>Импорт журнала ЧПУ…</translation>
    </message>
    <message>
        <source>CSV files (*.csv);;All files (*)</source>
        <translation>Файлы CSV (*.csv);;Все файлы (*)</translation>
    </message>
    <message>
        <source>The result shown is still that of the previous fit.</source>
        <translation>Показан результат предыдущего подбора.</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>Example data</source>
        <translation>Пример данных</translation>
    </message>
    <message>
        <source>Touches simulated for the probe and machine of the scenario, with a known answer: to try the fit before measuring your own.</source>
        <translation>Касания, смоделированные для датчика и станка из сценария, с известным ответом: чтобы опробовать подбор до собственных измерений.</translation>
    </message>
</context>
<context>
    <name>probecycle::ui::HelpGuide</name>
    <message>
        <source>One touch, phase by phase</source>
        <translation>Одно касание по фазам</translation>
    </message>
    <message>
        <source>The formulas</source>
        <translation>Формулы</translation>
    </message>
    <message>
        <source>Reading the charts</source>
        <translation>Как читать графики</translation>
    </message>
    <message>
        <source>&lt;b&gt;Cycle time against the probing feed&lt;/b&gt;: single-touch and two-touch (with the recommended backoff at each feed), the knee (the lowest feed whose cycle time is within the knee tolerance, 1 % by default, of the fastest valid cycle) and this cycle. Feeds whose cycle cannot run (overtravel over the limit, backoff too small) are invalid and never count as fast. &lt;b&gt;Overtravel and uncertainty&lt;/b&gt; against the feed, with the probe&apos;s limit and your target. &lt;b&gt;Phases&lt;/b&gt;: where the time goes. &lt;b&gt;Position and speed&lt;/b&gt; through the whole cycle.</source>
        <translation>&lt;b&gt;Время цикла в зависимости от подачи поиска&lt;/b&gt;: однократное и двукратное касание (с рекомендуемым отводом при каждой подаче), точка излома (наименьшая подача, время цикла при которой отличается от самого быстрого допустимого цикла не более чем на допуск излома, по умолчанию 1 %) и этот цикл. Подачи, при которых цикл невыполним (перебег сверх предела, слишком малый отвод), недопустимы и никогда не считаются быстрыми. &lt;b&gt;Перебег и неопределённость&lt;/b&gt; в зависимости от подачи, с пределом датчика и вашей целью. &lt;b&gt;Фазы&lt;/b&gt;: на что уходит время. &lt;b&gt;Положение и скорость&lt;/b&gt; на протяжении всего цикла.</translation>
    </message>
    <message>
        <source>Warnings</source>
        <translation>Предупреждения</translation>
    </message>
    <message>
        <source>Errors come first: an error means the cycle cannot run as set, and no cycle time is shown for it. Where a warning has a one-click fix, its button sets the value that clears it; Undo takes it back.</source>
        <translation>Ошибки идут первыми: ошибка значит, что цикл в таком виде невыполним, и время цикла для него не показывается. Если у предупреждения есть исправление одним щелчком, его кнопка ставит значение, которое его устраняет; «Отменить» возвращает прежнее.</translation>
    </message>
    <message>
        <source>Measuring the delay</source>
        <translation>Как измерить задержку</translation>
    </message>
    <message>
        <source>On the machine, touch the same surface at several feeds (for example 30, 100, 300, 1000 and 2000 mm/min, five times each), each time from far enough out to be at full feed, and note the recorded positions. Paste them into the Latency tab (axis, direction, feed, measured) and press Fit: measured = p&lt;sub&gt;0&lt;/sub&gt; + v &amp;middot; &amp;tau;, and the delay &amp;tau; = t&lt;sub&gt;i&lt;/sub&gt; + t&lt;sub&gt;c&lt;/sub&gt; + t&lt;sub&gt;s&lt;/sub&gt;/2 gives the controller&apos;s latency t&lt;sub&gt;c&lt;/sub&gt;, which Apply writes into the scenario. The Calibration tab fits the stylus&apos;s runout and effective radius from a ring gauge touched at spindle 0&amp;deg; and 180&amp;deg;.</source>
        <translation>На станке коснитесь одной и той же поверхности на нескольких подачах (например, 30, 100, 300, 1000 и 2000 мм/мин, по пять раз), каждый раз с такого расстояния, чтобы ось успела выйти на полную подачу, и запишите зафиксированные положения. Вставьте их на вкладке «Задержка» (ось, направление, подача, измерено) и нажмите «Подобрать»: измерено = p&lt;sub&gt;0&lt;/sub&gt; + v &amp;middot; &amp;tau;, а задержка &amp;tau; = t&lt;sub&gt;i&lt;/sub&gt; + t&lt;sub&gt;c&lt;/sub&gt; + t&lt;sub&gt;s&lt;/sub&gt;/2 даёт задержку ЧПУ t&lt;sub&gt;c&lt;/sub&gt;, которую кнопка «Применить к сценарию» записывает в сценарий. Вкладка «Калибровка» определяет биение и эффективный радиус наконечника по установочному кольцу, ощупанному при положении шпинделя 0&amp;deg; и 180&amp;deg;.</translation>
    </message>
    <message>
        <source>More</source>
        <translation>Подробнее</translation>
    </message>
    <message>
        <source>ProbeCycle guide</source>
        <translation>Руководство ProbeCycle</translation>
    </message>
    <message>
        <source>&lt;b&gt;Approach&lt;/b&gt;: from the start position to the surface at the probing feed. &lt;b&gt;Pretravel&lt;/b&gt;: the stylus deflects until the probe triggers. &lt;b&gt;Interface delay&lt;/b&gt; t&lt;sub&gt;i&lt;/sub&gt;: the probe&apos;s interface passes the signal on. &lt;b&gt;Controller delay&lt;/b&gt;: the control&apos;s latency t&lt;sub&gt;c&lt;/sub&gt; plus the wait until it scans the input, anything from nothing to a whole scan period t&lt;sub&gt;s&lt;/sub&gt;: the cycle time takes the mean wait, t&lt;sub&gt;s&lt;/sub&gt;/2, the overtravel the worst case, t&lt;sub&gt;s&lt;/sub&gt;. &lt;b&gt;Deceleration&lt;/b&gt;: the axis brakes to rest. Two-touch then &lt;b&gt;backs off&lt;/b&gt;, touches again slowly (the &lt;b&gt;2nd&lt;/b&gt; phases) and &lt;b&gt;returns&lt;/b&gt; to the start; a web, pocket, bore or boss adds the &lt;b&gt;positioning&lt;/b&gt; moves out from its centre to each touch and back. With a block change time, every move adds it (&lt;b&gt;block change&lt;/b&gt;).</source>
        <translation>&lt;b&gt;Подвод&lt;/b&gt;: от начальной точки до поверхности на подаче поиска. &lt;b&gt;Предход&lt;/b&gt;: наконечник щупа отклоняется, пока датчик не сработает. &lt;b&gt;Задержка интерфейса&lt;/b&gt; t&lt;sub&gt;i&lt;/sub&gt;: интерфейс датчика передаёт сигнал дальше. &lt;b&gt;Задержка ЧПУ&lt;/b&gt;: задержка системы ЧПУ t&lt;sub&gt;c&lt;/sub&gt; плюс ожидание, пока она не опросит вход, — от нуля до целого периода опроса t&lt;sub&gt;s&lt;/sub&gt;: время цикла учитывает среднее ожидание t&lt;sub&gt;s&lt;/sub&gt;/2, перебег — худший случай t&lt;sub&gt;s&lt;/sub&gt;. &lt;b&gt;Торможение&lt;/b&gt;: ось тормозит до остановки. Затем при двукратном касании следуют &lt;b&gt;отвод&lt;/b&gt;, повторное медленное касание (фазы &lt;b&gt;2-го&lt;/b&gt; касания) и &lt;b&gt;возврат&lt;/b&gt; в начальную точку; стенка, паз, отверстие или бобышка добавляют &lt;b&gt;позиционирование&lt;/b&gt; от центра к каждому касанию и обратно. Если задано время смены кадра, его добавляет каждое перемещение (&lt;b&gt;смена кадра&lt;/b&gt;).</translation>
    </message>
    <message>
        <source>Overtravel = pretravel + v &amp;middot; (t&lt;sub&gt;i&lt;/sub&gt; + t&lt;sub&gt;c&lt;/sub&gt; + t&lt;sub&gt;s&lt;/sub&gt;) + the braking distance (v&amp;middot;T/2 with a time constant T), the worst case; on average the axis stops v &amp;middot; t&lt;sub&gt;s&lt;/sub&gt;/2 short of it, and a two-touch cycle&apos;s second approach is the backoff less that mean stop. Scan range R = v &amp;middot; t&lt;sub&gt;s&lt;/sub&gt; (0 with a latched input). The trigger&apos;s uncertainty (k = 2) U&lt;sub&gt;t&lt;/sub&gt; = &amp;radic;(R&amp;sup2;/3 + repeatability&amp;sup2;), over &amp;radic;N for N repeats; the uncertainty (k = 2) is its budget with the terms no feed changes, U = &amp;radic;(U&lt;sub&gt;t&lt;/sub&gt;&amp;sup2; + 4 (lobing&amp;sup2;/3 + artefact&amp;sup2;/4 + machine repeatability&amp;sup2;/4 + thermal drift&amp;sup2;/3)). Recommended backoff = the first touch&apos;s overtravel + the larger of the reseat distance and the distance the second touch needs to reach its feed, rounded up to the micrometre. The tooltip of every parameter says where it enters.</source>
        <translation>Перебег = предход + v &amp;middot; (t&lt;sub&gt;i&lt;/sub&gt; + t&lt;sub&gt;c&lt;/sub&gt; + t&lt;sub&gt;s&lt;/sub&gt;) + тормозной путь (v&amp;middot;T/2 при постоянной времени T), худший случай; в среднем ось останавливается, не доходя до этой точки v &amp;middot; t&lt;sub&gt;s&lt;/sub&gt;/2, и второй подвод двукратного касания равен отводу за вычетом этой средней остановки. Разброс опроса R = v &amp;middot; t&lt;sub&gt;s&lt;/sub&gt; (0 при входе с защёлкой). Неопределённость срабатывания (k = 2) U&lt;sub&gt;t&lt;/sub&gt; = &amp;radic;(R&amp;sup2;/3 + повторяемость&amp;sup2;), делённая на &amp;radic;N при N повторах; неопределённость (k = 2) — её бюджет вместе с членами, не зависящими от подачи: U = &amp;radic;(U&lt;sub&gt;t&lt;/sub&gt;&amp;sup2; + 4 (лепестковость&amp;sup2;/3 + эталон&amp;sup2;/4 + повторяемость станка&amp;sup2;/4 + температурный дрейф&amp;sup2;/3)). Рекомендуемый отвод = перебег первого касания + большее из пути восстановления датчика и пути разгона второго касания до его подачи, с округлением вверх до микрометра. Подсказка каждого параметра говорит, где он входит в модель.</translation>
    </message>
    <message>
        <source>Getting started</source>
        <translation>С чего начать</translation>
    </message>
    <message>
        <source>&lt;b&gt;1. Start near your machine.&lt;/b&gt; Choose the preset closest to your control and probe (Presets), or read a LinuxCNC machine from its INI file (File &amp;gt; Import Machine). Every value is typical until you replace it with yours. &lt;b&gt;2. Enter what you know.&lt;/b&gt; From the probe&apos;s data sheet: its pretravel, repeatability and overtravel limit; from the control: its scan period; from your cycle: the feature, the feeds and the backoff. What you do not know, the delays, you measure in the Latency tab (its Example data shows how). &lt;b&gt;3. Read the six numbers at the top.&lt;/b&gt; Cycle time: the whole cycle as set. Overtravel: how far the axis runs past the trigger, against the probe&apos;s limit, at the highest feed override. Trigger speed: the feed when the measuring touch triggers. Uncertainty (k = 2): the measurement&apos;s budget; its tooltip lists the terms. Recommended backoff: the least that lets the second touch reseat and reach its feed. Knee: the feed beyond which a faster search saves almost no time. &lt;b&gt;4. Follow the warnings&lt;/b&gt;, errors first; each button sets the value that clears its warning, and the Optimise tab finds the fastest settings that meet your limits. &lt;b&gt;Where the numbers come from&lt;/b&gt;: a model of the axis&apos;s motion (acceleration, filters, servo lag), the probe and the control&apos;s delays, with the formulas below; nothing is measured unless you measure it.</source>
        <translation>&lt;b&gt;1. Начните с близкого к вашему станку.&lt;/b&gt; Выберите предустановку, ближайшую к вашему ЧПУ и датчику (Предустановки), или прочитайте станок LinuxCNC из его INI-файла (Файл &amp;gt; Импорт станка). Все значения типовые, пока вы не замените их своими. &lt;b&gt;2. Введите то, что знаете.&lt;/b&gt; Из паспорта датчика: предход, повторяемость и предел перебега; из ЧПУ: период опроса; из вашего цикла: элемент, подачи и отвод. То, чего вы не знаете, — задержки — измеряется на вкладке «Задержка» (её «Пример данных» показывает как). &lt;b&gt;3. Прочитайте шесть чисел вверху.&lt;/b&gt; Время цикла: весь цикл как задан. Перебег: насколько ось проходит за точку срабатывания, в сравнении с пределом датчика, при наибольшей коррекции подачи. Скорость срабатывания: подача в момент срабатывания измерительного касания. Неопределённость (k = 2): бюджет измерения; её подсказка перечисляет члены. Рекомендуемый отвод: наименьший, при котором второе касание успевает восстановить датчик и выйти на свою подачу. Точка излома: подача, выше которой более быстрый поиск почти не экономит время. &lt;b&gt;4. Следуйте предупреждениям&lt;/b&gt;, сначала ошибкам; кнопка каждого задаёт значение, которое его снимает, а вкладка «Оптимизация» находит самые быстрые настройки в ваших пределах. &lt;b&gt;Откуда берутся числа&lt;/b&gt;: из модели движения оси (разгон, фильтры, запаздывание привода), датчика и задержек ЧПУ, с формулами ниже; ничто не измерено, пока вы этого не измерите.</translation>
    </message>
    <message>
        <source>The README and the docs folder beside it explain the model in full, with its limits, the files, the command line and the lab. &lt;a href=&quot;%1&quot;&gt;Open the README&lt;/a&gt;.</source>
        <translation>README и папка docs рядом с ним описывают модель полностью, с её ограничениями, файлами, командной строкой и лабораторией. &lt;a href=&quot;%1&quot;&gt;Открыть README&lt;/a&gt;.</translation>
    </message>
</context>
<context>
    <name>probecycle::ui::Lab</name>
    <message>
        <source>Points on one side</source>
        <translation>Точки с одной стороны</translation>
    </message>
    <message>
        <source>Large stylus runout</source>
        <translation>Большое биение наконечника</translation>
    </message>
    <message>
        <source>Point off the circle</source>
        <translation>Точка вне окружности</translation>
    </message>
    <message>
        <source>One orientation only: no runout</source>
        <translation>Только одна ориентация: биения нет</translation>
    </message>
    <message>
        <source>Three points: exact fit</source>
        <translation>Три точки: точный подбор</translation>
    </message>
    <message>
        <source>Length far from the nominal</source>
        <translation>Длина далека от номинальной</translation>
    </message>
    <message>
        <source>Fewer than 3 feeds</source>
        <translation>Меньше 3 подач</translation>
    </message>
    <message>
        <source>Unstable delay</source>
        <translation>Нестабильная задержка</translation>
    </message>
    <message>
        <source>Residuals curve: the delay changes</source>
        <translation>Остатки искривлены: задержка меняется</translation>
    </message>
    <message>
        <source>Negative delay</source>
        <translation>Отрицательная задержка</translation>
    </message>
    <message>
        <source>One touch at a feed</source>
        <translation>Одно касание на подаче</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <extracomment>%1 the group (&quot;X+&quot;), %2 the warning&apos;s title</extracomment>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>Файлы CSV (*.csv)</translation>
    </message>
    <message>
        <source>%1 could not be written: %2</source>
        <translation>Не удалось записать %1: %2</translation>
    </message>
</context>
<context>
    <name>probecycle::ui::MachineLogDialog</name>
    <message>
        <source>delay-stability test</source>
        <translation>испытание стабильности задержки</translation>
    </message>
    <message>
        <source>ring-gauge calibration</source>
        <translation>калибровка по установочному кольцу</translation>
    </message>
    <message>
        <source>tuned cycle</source>
        <translation>настроенный цикл</translation>
    </message>
    <message>
        <source>%1 is not a probing plan:
%2</source>
        <extracomment>%1 the plan file, %2 what is wrong in it (one problem a line)</extracomment>
        <translation>%1 — не план измерения:
%2</translation>
    </message>
    <message>
        <source>%1 is the plan of a %2 program; this tab reads the log of a %3 program.</source>
        <extracomment>%1 the plan file, %2 its program (&quot;ring-gauge calibration&quot;), %3 this tab&apos;s</extracomment>
        <translation>%1 — план программы «%2»; эта вкладка читает журнал программы «%3».</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <extracomment>%1 the machine log&apos;s file, %2 the problem with its line</extracomment>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>Import machine log</source>
        <translation>Импорт журнала ЧПУ</translation>
    </message>
    <message>
        <source>What the control recorded while it ran a %1 program of ProbeCycle&apos;s, with the plan saved beside the program. The positions fill the paste box and are fitted; on any problem nothing changes.</source>
        <extracomment>%1 the program (&quot;delay-stability test&quot;)</extracomment>
        <translation>То, что ЧПУ записала при выполнении программы ProbeCycle «%1», вместе с планом, сохранённым рядом с программой. Положения попадают в поле ввода и подбираются; при любой ошибке ничего не меняется.</translation>
    </message>
    <message>
        <source>Control</source>
        <translation>ЧПУ</translation>
    </message>
    <message>
        <source>The log the program writes: probecycle_log.txt in LinuxCNC&apos;s working directory.</source>
        <translation>Журнал, который пишет программа: probecycle_log.txt в рабочем каталоге LinuxCNC.</translation>
    </message>
    <message>
        <source>The sender&apos;s console saved to a file: grbl answers [PRB:x,y,z:1] after each probe (set $13=0 for mm).</source>
        <translation>Консоль программы-отправителя, сохранённая в файл: grbl отвечает [PRB:x,y,z:1] после каждого касания (для мм задайте $13=0).</translation>
    </message>
    <message>
        <source>Plan</source>
        <translation>План</translation>
    </message>
    <message>
        <source>NAME.plan.json, saved with the program</source>
        <translation>ИМЯ.plan.json, сохранённый вместе с программой</translation>
    </message>
    <message>
        <source>Browse…</source>
        <translation>Обзор…</translation>
    </message>
    <message>
        <source>Log</source>
        <translation>Журнал</translation>
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
        <source>Choose the plan</source>
        <translation>Выбор плана</translation>
    </message>
    <message>
        <source>Probing plans (*.plan.json *.json);;All files (*)</source>
        <translation>Планы измерения (*.plan.json *.json);;Все файлы (*)</translation>
    </message>
    <message>
        <source>Choose the machine log</source>
        <translation>Выбор журнала ЧПУ</translation>
    </message>
    <message>
        <source>Logs (*.txt *.log);;All files (*)</source>
        <translation>Журналы (*.txt *.log);;Все файлы (*)</translation>
    </message>
    <message>
        <source>The program&apos;s DPRNT output as the control sent it (a serial terminal, a memory card or a file): the lines from PROBECYCLE PLAN on.</source>
        <translation>Вывод DPRNT программы в том виде, в каком его передала стойка (последовательный терминал, карта памяти или файл): строки начиная с PROBECYCLE PLAN.</translation>
    </message>
    <message>
        <source>The common variables #500 to #999 after the program ended, as the control outputs them or copied from its variable screen: one line &quot;#n value&quot; each.</source>
        <translation>Общие переменные #500–#999 после завершения программы, как их выводит стойка или как они скопированы с экрана переменных: по одной строке «#n значение».</translation>
    </message>
    <message>
        <source>The file PROBECYCLE_LOG that the program&apos;s WRITE appends to, copied from the control: its last run is read.</source>
        <translation>Файл PROBECYCLE_LOG, в который дописывает WRITE программы, скопированный со стойки: читается его последний прогон.</translation>
    </message>
</context>
<context>
    <name>probecycle::ui::MainWindow</name>
    <message>
        <source>About ProbeCycle</source>
        <translation>О программе ProbeCycle</translation>
    </message>
    <message>
        <source>&lt;p&gt;&lt;b&gt;ProbeCycle&lt;/b&gt; %1&lt;/p&gt;&lt;p&gt;Cycle time, overtravel and uncertainty of touch-trigger probing cycles on CNC machine tools.&lt;/p&gt;&lt;p&gt;Every value in the model is a typical one until you replace it with your measured value.&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;ProbeCycle&lt;/b&gt; %1&lt;/p&gt;&lt;p&gt;Время цикла, перебег и неопределённость циклов измерения контактными датчиками на станках с ЧПУ.&lt;/p&gt;&lt;p&gt;Каждое значение в модели остаётся типовым, пока вы не замените его измеренным.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&amp;New</source>
        <translation>&amp;Новый</translation>
    </message>
    <message>
        <source>Start from the default scenario (typical values)</source>
        <translation>Начать со сценария по умолчанию (типовые значения)</translation>
    </message>
    <message>
        <source>&amp;Open…</source>
        <translation>&amp;Открыть…</translation>
    </message>
    <message>
        <source>Open a scenario file (the JSON the command-line tool reads)</source>
        <translation>Открыть файл сценария (JSON, который читает консольная программа)</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>&amp;Сохранить</translation>
    </message>
    <message>
        <source>Save the scenario as JSON</source>
        <translation>Сохранить сценарий в JSON</translation>
    </message>
    <message>
        <source>Save &amp;As…</source>
        <translation>Сохранить &amp;как…</translation>
    </message>
    <message>
        <source>Export CSV &amp;Report…</source>
        <translation>Экспорт &amp;отчёта CSV…</translation>
    </message>
    <message>
        <source>Scenario, summary, phases, warnings and a feed sweep as CSV, the same as the command-line tool writes</source>
        <translation>Сценарий, сводка, фазы, предупреждения и перебор подач в CSV — так же, как пишет консольная программа</translation>
    </message>
    <message>
        <source>Export Charts as &amp;PNG…</source>
        <translation>Экспорт графиков в &amp;PNG…</translation>
    </message>
    <message>
        <source>Save the four charts as one PNG image</source>
        <translation>Сохранить четыре графика одним изображением PNG</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>В&amp;ыход</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Отменить</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Повторить</translation>
    </message>
    <message>
        <source>Undo</source>
        <translation>Отменить</translation>
    </message>
    <message>
        <source>&amp;Pin Baseline</source>
        <translation>&amp;Закрепить базу</translation>
    </message>
    <message>
        <source>Keep the current scenario as a baseline: its curves stay drawn dashed and the readouts show the difference</source>
        <translation>Сохранить текущий сценарий как базу: его кривые остаются штриховыми, а показания выводят разницу</translation>
    </message>
    <message>
        <source>&amp;Clear Baseline</source>
        <translation>&amp;Убрать базу</translation>
    </message>
    <message>
        <source>&amp;About ProbeCycle</source>
        <translation>&amp;О программе ProbeCycle</translation>
    </message>
    <message>
        <source>Presets hold typical values: replace them with measured ones</source>
        <translation>Предустановки содержат типовые значения: замените их измеренными</translation>
    </message>
    <message>
        <source>System language</source>
        <translation>Язык системы</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Файл</translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation>&amp;Недавние файлы</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>&amp;Правка</translation>
    </message>
    <message>
        <source>&amp;Presets</source>
        <translation>П&amp;редустановки</translation>
    </message>
    <message>
        <source>P&amp;robe class</source>
        <translation>&amp;Класс датчика</translation>
    </message>
    <message>
        <source>&amp;Compare</source>
        <translation>С&amp;равнение</translation>
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
        <source>Warnings</source>
        <translation>Предупреждения</translation>
    </message>
    <message>
        <source>Main toolbar</source>
        <translation>Главная панель</translation>
    </message>
    <message>
        <source>Unsaved changes</source>
        <translation>Несохранённые изменения</translation>
    </message>
    <message>
        <source>Save the changes to %1?</source>
        <translation>Сохранить изменения в %1?</translation>
    </message>
    <message>
        <source>change %1</source>
        <translation>изменение: %1</translation>
    </message>
    <message>
        <source>Default scenario: typical values, to be replaced with measured ones</source>
        <translation>Сценарий по умолчанию: типовые значения, замените их измеренными</translation>
    </message>
    <message>
        <source>Could not open the scenario</source>
        <translation>Не удалось открыть сценарий</translation>
    </message>
    <message>
        <source>%1 could not be read: %2</source>
        <translation>Не удалось прочитать %1: %2</translation>
    </message>
    <message>
        <source>%1 is not a valid scenario:
%2</source>
        <translation>%1 — недопустимый сценарий:
%2</translation>
    </message>
    <message>
        <source>Opened %1</source>
        <translation>Открыт %1</translation>
    </message>
    <message>
        <source>Could not save the scenario</source>
        <translation>Не удалось сохранить сценарий</translation>
    </message>
    <message>
        <source>%1 could not be written: %2</source>
        <translation>Не удалось записать %1: %2</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>Сохранено: %1</translation>
    </message>
    <message>
        <source>Could not export the report</source>
        <translation>Не удалось экспортировать отчёт</translation>
    </message>
    <message>
        <source>The scenario is not valid; see the warnings panel.</source>
        <translation>Сценарий недопустим; см. панель предупреждений.</translation>
    </message>
    <message>
        <source>Report written to %1</source>
        <translation>Отчёт записан в %1</translation>
    </message>
    <message>
        <source>Could not export the charts</source>
        <translation>Не удалось экспортировать графики</translation>
    </message>
    <message>
        <source>Charts written to %1</source>
        <translation>Графики записаны в %1</translation>
    </message>
    <message>
        <source>Could not apply the preset</source>
        <translation>Не удалось применить предустановку</translation>
    </message>
    <message>
        <source>preset %1</source>
        <translation>предустановка %1</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>(нет)</translation>
    </message>
    <message>
        <source>Export CSV report</source>
        <translation>Экспорт отчёта CSV</translation>
    </message>
    <message>
        <source>CSV (*.csv)</source>
        <translation>CSV (*.csv)</translation>
    </message>
    <message>
        <source>Export charts as PNG</source>
        <translation>Экспорт графиков в PNG</translation>
    </message>
    <message>
        <source>PNG image (*.png)</source>
        <translation>Изображение PNG (*.png)</translation>
    </message>
    <message>
        <source>Baseline pinned: change parameters to compare against it</source>
        <translation>База закреплена: меняйте параметры, чтобы сравнить с ней</translation>
    </message>
    <message>
        <source>set backoff to recommended</source>
        <translation>отвод по рекомендации</translation>
    </message>
    <message>
        <source>drop feed to the knee</source>
        <translation>подача до точки излома</translation>
    </message>
    <message>
        <source>start far enough out to reach the feed</source>
        <translation>начало подхода дальше для разгона</translation>
    </message>
    <message>
        <source>&amp;Undo %1</source>
        <translation>&amp;Отменить: %1</translation>
    </message>
    <message>
        <source>&amp;Redo %1</source>
        <translation>&amp;Повторить: %1</translation>
    </message>
    <message>
        <source>Redo</source>
        <translation>Повторить</translation>
    </message>
    <message>
        <source>apply the measured delay</source>
        <translation>применить измеренную задержку</translation>
    </message>
    <message>
        <source>Cycle</source>
        <translation>Цикл</translation>
    </message>
    <message>
        <source>Calibration</source>
        <translation>Калибровка</translation>
    </message>
    <message>
        <source>Latency</source>
        <translation>Задержка</translation>
    </message>
    <message>
        <source>the image could not be encoded as PNG</source>
        <translation>не удалось закодировать изображение в PNG</translation>
    </message>
    <message>
        <source>Comparison</source>
        <translation>Сравнение</translation>
    </message>
    <message>
        <source>&amp;Machine (skip input, control)</source>
        <translation>&amp;Станок (вход пропуска, ЧПУ)</translation>
    </message>
    <message>
        <source>Cycle (%1)</source>
        <translation>Цикл (%1)</translation>
    </message>
    <message>
        <source>drop feed for the overtravel</source>
        <translation>снизить подачу ради перебега</translation>
    </message>
    <message>
        <source>Errors: %1</source>
        <translation>Ошибок: %1</translation>
    </message>
    <message>
        <source>Warnings: %1</source>
        <translation>Предупреждений: %1</translation>
    </message>
    <message>
        <source>Notes: %1</source>
        <translation>Замечаний: %1</translation>
    </message>
    <message>
        <source>on</source>
        <translation>вкл.</translation>
    </message>
    <message>
        <source>off</source>
        <translation>выкл.</translation>
    </message>
    <message>
        <source>%1: nothing to change, the values are already the preset&apos;s</source>
        <translation>%1: менять нечего, значения уже как в предустановке</translation>
    </message>
    <message>
        <source>%1: typical values applied (Undo restores): %2</source>
        <translation>%1: применены типовые значения (отмена возвращает прежние): %2</translation>
    </message>
    <message>
        <source>%1 - %2 - %3 - ProbeCycle %4</source>
        <translation>%1 — %2 — %3 — ProbeCycle %4</translation>
    </message>
    <message>
        <source>&amp;Guide</source>
        <translation>&amp;Руководство</translation>
    </message>
    <message>
        <source>The project you open replaces the lab&apos;s data (touches, fits, comparison settings), which is in no project file yet. Save everything as a project first?</source>
        <translation>Открываемый проект заменит данные лаборатории (касания, подгонки, настройки сравнения), которые ещё не сохранены ни в одном файле проекта. Сначала сохранить всё как проект?</translation>
    </message>
    <message>
        <source>Could not open the project</source>
        <translation>Не удалось открыть проект</translation>
    </message>
    <message>
        <source>%1 is not a valid project:
%2</source>
        <translation>%1 — недопустимый проект:
%2</translation>
    </message>
    <message>
        <source>Could not save the project</source>
        <translation>Не удалось сохранить проект</translation>
    </message>
    <message>
        <source>Open scenario or project</source>
        <translation>Открыть сценарий или проект</translation>
    </message>
    <message>
        <source>Scenarios and projects (*.json *.probecycle);;Project (*.probecycle);;Scenario (*.json);;All files (*)</source>
        <translation>Сценарии и проекты (*.json *.probecycle);;Проект (*.probecycle);;Сценарий (*.json);;Все файлы (*)</translation>
    </message>
    <message>
        <source>ProbeCycle project: scenario, lab and comparison (*.probecycle)</source>
        <translation>Проект ProbeCycle: сценарий, лаборатория и сравнение (*.probecycle)</translation>
    </message>
    <message>
        <source>Scenario only (*.json)</source>
        <translation>Только сценарий (*.json)</translation>
    </message>
    <message>
        <source>Save as</source>
        <translation>Сохранить как</translation>
    </message>
    <message>
        <source>Export P&amp;DF Report…</source>
        <translation>Экспорт отчёта в P&amp;DF…</translation>
    </message>
    <message>
        <source>A4 pages to hand over: the current tab&apos;s results, charts, warnings with their fixes and the inputs, in the interface&apos;s language</source>
        <translation>Страницы A4 для передачи: результаты текущей вкладки, графики, предупреждения с исправлениями и исходные данные, на языке интерфейса</translation>
    </message>
    <message>
        <source>Export PDF report</source>
        <translation>Экспорт отчёта в PDF</translation>
    </message>
    <message>
        <source>PDF (*.pdf)</source>
        <translation>PDF (*.pdf)</translation>
    </message>
    <message>
        <source>yes</source>
        <translation>используется</translation>
    </message>
    <message>
        <source>no</source>
        <translation>не используется</translation>
    </message>
    <message>
        <source>ProbeCycle report: %1</source>
        <translation>Отчёт ProbeCycle: %1</translation>
    </message>
    <message>
        <source>Figures computed by ProbeCycle %1 from a model of the machine, probe and cycle with the inputs listed in this report. They are estimates for setting up the cycle, not a calibration certificate.</source>
        <translation>Значения рассчитаны ProbeCycle %1 по модели станка, щупа и цикла с исходными данными, приведёнными в этом отчёте. Это оценки для наладки цикла, а не свидетельство о калибровке.</translation>
    </message>
    <message>
        <source>%1 · %2 · ProbeCycle %3</source>
        <translation>%1 · %2 · ProbeCycle %3</translation>
    </message>
    <message>
        <source>No results yet: %1</source>
        <translation>Результатов пока нет: %1</translation>
    </message>
    <message>
        <source>Results</source>
        <translation>Результаты</translation>
    </message>
    <message>
        <source>Quantity</source>
        <translation>Величина</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Значение</translation>
    </message>
    <message>
        <source>Detail</source>
        <translation>Подробности</translation>
    </message>
    <message>
        <source>Warnings and what to change</source>
        <translation>Предупреждения и что изменить</translation>
    </message>
    <message>
        <source>No warnings: the cycle runs as set.</source>
        <translation>Предупреждений нет: цикл выполняется как задан.</translation>
    </message>
    <message>
        <source>The scenario</source>
        <translation>Сценарий</translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation>Параметр</translation>
    </message>
    <message>
        <source>Key</source>
        <translation>Ключ</translation>
    </message>
    <message>
        <source>Could not export the PDF report</source>
        <translation>Не удалось экспортировать отчёт в PDF</translation>
    </message>
    <message>
        <source>PDF report written to %1</source>
        <translation>Отчёт PDF записан в %1</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <extracomment>%1 the severity (Error, Warning, Note), %2 the warning&apos;s title</extracomment>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>apply the best settings</source>
        <translation>применить лучшие настройки</translation>
    </message>
    <message>
        <source>Optimise</source>
        <translation>Оптимизация</translation>
    </message>
    <message>
        <source>The optimiser&apos;s recommendation</source>
        <translation>Рекомендация оптимизатора</translation>
    </message>
    <message>
        <source>The scenario is not valid; see the warnings.</source>
        <translation>Сценарий недопустим; см. предупреждения.</translation>
    </message>
    <message>
        <source>Program for the &amp;Control…</source>
        <translation>Программа для &amp;ЧПУ…</translation>
    </message>
    <message>
        <source>The cycle as a probing program for your control (LinuxCNC, grbl, Fanuc, Haas, Mitsubishi, Siemens), with the values set here</source>
        <translation>Цикл как программа измерения для вашей ЧПУ (LinuxCNC, grbl, Fanuc, Haas, Mitsubishi, Siemens) со значениями, заданными здесь</translation>
    </message>
    <message>
        <source>&amp;LinuxCNC INI…</source>
        <translation>&amp;LinuxCNC INI…</translation>
    </message>
    <message>
        <source>The machine from a LinuxCNC 2.9 configuration: the axes&apos; acceleration and speed limits and the servo period, as ProbeCycle&apos;s LinuxCNC programs (exact stop) meet them. The drives&apos; lag is not in the file and is set to none.</source>
        <translation>Станок из конфигурации LinuxCNC 2.9: пределы ускорения и скорости осей и период сервоцикла так, как они действуют на программы ProbeCycle для LinuxCNC (точный останов). Запаздывания приводов в файле нет, оно принимается нулевым.</translation>
    </message>
    <message>
        <source>&amp;Import Machine</source>
        <translation>&amp;Импорт станка</translation>
    </message>
    <message>
        <source>Could not import the machine</source>
        <translation>Не удалось импортировать станок</translation>
    </message>
    <message>
        <source>%1 is not a valid LinuxCNC configuration:
%2</source>
        <translation>%1 — недопустимая конфигурация LinuxCNC:
%2</translation>
    </message>
    <message>
        <source>import the machine from %1</source>
        <translation>импорт станка из %1</translation>
    </message>
    <message>
        <source>%1: nothing to change, the machine is already this one</source>
        <translation>%1: менять нечего, станок уже такой</translation>
    </message>
    <message>
        <source>%1: machine imported (Undo restores): %2</source>
        <translation>%1: станок импортирован (отмена возвращает прежние значения): %2</translation>
    </message>
    <message>
        <source>Import the machine from a LinuxCNC INI file</source>
        <translation>Импорт станка из INI-файла LinuxCNC</translation>
    </message>
    <message>
        <source>LinuxCNC configuration (*.ini *.expanded);;All files (*)</source>
        <translation>Конфигурация LinuxCNC (*.ini *.expanded);;Все файлы (*)</translation>
    </message>
    <message>
        <source>search past the touch&apos;s stop</source>
        <translation>поиск за точку остановки касания</translation>
    </message>
    <message>
        <source>drop the positioning feed for the overtravel</source>
        <translation>снизить подачу позиционирования ради перебега</translation>
    </message>
    <message>
        <source>Uncertainty budget</source>
        <translation>Бюджет неопределённости</translation>
    </message>
    <message>
        <source>%1 points: the tables give their statistics and the %2 that deviate most. The CSV report (Export report…) has every point.</source>
        <translation>Точек: %1. Таблицы дают их статистику и %2 точек с наибольшим отклонением. В отчёте CSV (Экспорт отчёта…) есть все точки.</translation>
    </message>
    <message>
        <source>There is no preset %1.</source>
        <translation>Предустановки %1 нет.</translation>
    </message>
    <message>
        <source>Report De&amp;tails…</source>
        <translation>&amp;Данные отчёта…</translation>
    </message>
    <message>
        <source>Customer, machine, part, author and notes for the top of the PDF report</source>
        <translation>Заказчик, станок, деталь, автор и примечания для заголовка отчёта PDF</translation>
    </message>
    <message>
        <source>Charts</source>
        <translation>Графики</translation>
    </message>
    <message>
        <source>Suggested change: %1</source>
        <translation>Рекомендуемое изменение: %1</translation>
    </message>
</context>
<context>
    <name>probecycle::ui::OptimisePanel</name>
    <message>
        <source>The current settings do not meet the requirements; the fastest that do take %1 a cycle.</source>
        <translation>Текущие настройки не удовлетворяют требованиям; самые быстрые из удовлетворяющих дают %1 на цикл.</translation>
    </message>
    <message>
        <source>The current settings are already the fastest that meet the requirements.</source>
        <translation>Текущие настройки уже самые быстрые из удовлетворяющих требованиям.</translation>
    </message>
    <message>
        <source>The best settings save %1 a cycle: %2 instead of %3 (%4 % less).</source>
        <translation>Лучшие настройки экономят %1 за цикл: %2 вместо %3 (на %4 % меньше).</translation>
    </message>
    <message>
        <source>a cycle that can run (the backoff and the probe&apos;s overtravel limit)</source>
        <translation>выполнимость цикла (отвод и предел перебега щупа)</translation>
    </message>
    <message>
        <source>the target uncertainty, %1</source>
        <translation>целевая неопределённость, %1</translation>
    </message>
    <message>
        <source>the current uncertainty, %1 (no target is set)</source>
        <translation>текущая неопределённость, %1 (цель не задана)</translation>
    </message>
    <message>
        <source>the overtravel allowed, %1 % of the probe&apos;s limit</source>
        <translation>допустимый перебег, %1 % от предела щупа</translation>
    </message>
    <message>
        <source>the probe&apos;s maximum feed, %1</source>
        <translation>максимальная подача щупа, %1</translation>
    </message>
    <message>
        <source>the machine&apos;s rapid feed, %1</source>
        <translation>ускоренная подача станка, %1</translation>
    </message>
    <message>
        <source>at most %1 measurements</source>
        <translation>не более %1 измерений</translation>
    </message>
    <message>
        <source>What limits it: %1.</source>
        <translation>Ограничивает: %1.</translation>
    </message>
    <message>
        <source>Saved per part: %1; per year: %2 h of machine time</source>
        <translation>Экономия на деталь: %1; за год: %2 ч работы станка</translation>
    </message>
    <message>
        <source>, worth %1 at the machine rate</source>
        <translation>, что составляет %1 по стоимости станко-часа</translation>
    </message>
    <message>
        <source>What else would save time:</source>
        <translation>Что ещё сэкономило бы время:</translation>
    </message>
    <message>
        <source>Requirements</source>
        <translation>Требования</translation>
    </message>
    <message>
        <source>Overtravel allowed, of the probe&apos;s limit</source>
        <translation>Допустимый перебег, от предела щупа</translation>
    </message>
    <message>
        <source>The optimiser keeps the overtravel at or under this share of the probe&apos;s overtravel limit (80 %: where the cycle starts to warn).</source>
        <translation>Оптимизатор держит перебег не выше этой доли предела перебега щупа (80 %: порог, с которого цикл предупреждает).</translation>
    </message>
    <message>
        <source>Current</source>
        <translation>Текущие</translation>
    </message>
    <message>
        <source>Best</source>
        <translation>Лучшие</translation>
    </message>
    <message>
        <source>Strategy</source>
        <translation>Стратегия</translation>
    </message>
    <message>
        <source>Probing feedrate</source>
        <translation>Скорость подачи поиска</translation>
    </message>
    <message>
        <source>Measuring feedrate</source>
        <translation>Измерительная подача</translation>
    </message>
    <message>
        <source>Backoff</source>
        <translation>Отвод</translation>
    </message>
    <message>
        <source>Measurements</source>
        <translation>Число измерений</translation>
    </message>
    <message>
        <source>Cycle time</source>
        <translation>Время цикла</translation>
    </message>
    <message>
        <source>Uncertainty (k = 2)</source>
        <translation>Неопределённость (k = 2)</translation>
    </message>
    <message>
        <source>Overtravel</source>
        <translation>Перебег</translation>
    </message>
    <message>
        <source>Apply the best settings</source>
        <translation>Применить лучшие настройки</translation>
    </message>
    <message>
        <source>Sets strategy, feeds, backoff, start distance and measurements to the best ones, as one step that Undo takes back</source>
        <translation>Устанавливает лучшие стратегию, подачи, отвод, расстояние подхода и число измерений одним шагом, который отменяется командой «Отменить»</translation>
    </message>
    <message>
        <source>Fastest cycle at each uncertainty</source>
        <translation>Самый быстрый цикл при каждой неопределённости</translation>
    </message>
    <message>
        <source>Uncertainty, k = 2 [µm]</source>
        <translation>Неопределённость, k = 2 [мкм]</translation>
    </message>
    <message>
        <source>Cycle time [s]</source>
        <translation>Время цикла [с]</translation>
    </message>
    <message>
        <source>Fastest valid settings</source>
        <translation>Самые быстрые допустимые настройки</translation>
    </message>
    <message>
        <source>Approach distance</source>
        <translation>Расстояние подхода</translation>
    </message>
    <message>
        <source>Positioning feed</source>
        <translation>Подача позиционирования</translation>
    </message>
    <message>
        <source>Target uncertainty</source>
        <translation>Целевая неопределённость</translation>
    </message>
    <message>
        <source>Current uncertainty</source>
        <translation>Текущая неопределённость</translation>
    </message>
    <message>
        <source>the start distance: at least %1, and the part&apos;s position uncertainty plus the distance to reach the probing feed</source>
        <translation>начальное расстояние: не меньше %1, и неопределённость положения детали плюс путь разгона до подачи поиска</translation>
    </message>
    <message>
        <source>the slowest feed allowed, %1</source>
        <translation>наименьшая допустимая подача, %1</translation>
    </message>
    <message>
        <source>Overtravel at %1 %</source>
        <translation>Перебег при %1 %</translation>
    </message>
</context>
<context>
    <name>probecycle::ui::ParameterPanel</name>
    <message>
        <source>Typical values: replace them with your measured ones.</source>
        <translation>Типовые значения: замените их измеренными.</translation>
    </message>
    <message>
        <source>The defaults and the presets are typical values for a machining centre and its probe. Replace them with the ones measured on your machine.</source>
        <translation>Значения по умолчанию и предустановки — типовые для обрабатывающего центра и его датчика. Замените их измеренными на вашем станке.</translation>
    </message>
</context>
<context>
    <name>probecycle::ui::PasteBox</name>
    <message>
        <source>%1 could not be read: %2</source>
        <translation>Не удалось прочитать %1: %2</translation>
    </message>
</context>
<context>
    <name>probecycle::ui::ProgramDialog</name>
    <message>
        <source>Ring-gauge calibration program</source>
        <translation>Программа калибровки по установочному кольцу</translation>
    </message>
    <message>
        <source>From the gauge centre: X+, X−, Y+, Y− with the spindle at 0°, a pause to turn it to 180°, the same four, each point with the scenario&apos;s strategy and feeds. Every move is incremental from where the probe stands. Save the plan with the program: &quot;Import machine log…&quot; needs it.</source>
        <translation>От центра кольца: X+, X−, Y+, Y− при шпинделе в 0°, пауза для поворота на 180°, те же четыре точки; каждая точка — со стратегией и подачами сценария. Все перемещения в приращениях от текущего положения датчика. Сохраните план вместе с программой: он нужен для «Импорт журнала ЧПУ…».</translation>
    </message>
    <message>
        <source>Gauge diameter</source>
        <translation>Диаметр кольца</translation>
    </message>
    <message>
        <source>The calibrated diameter of the ring gauge, from its certificate.</source>
        <translation>Аттестованный диаметр установочного кольца по его сертификату.</translation>
    </message>
    <message>
        <source>Ball diameter</source>
        <translation>Диаметр шарика</translation>
    </message>
    <message>
        <source>The stylus ball&apos;s diameter: the room to the wall is the gauge&apos;s radius less the ball&apos;s.</source>
        <translation>Диаметр шарика наконечника: расстояние до стенки — радиус кольца минус радиус шарика.</translation>
    </message>
    <message>
        <source>Centre tolerance</source>
        <translation>Допуск центра</translation>
    </message>
    <message>
        <source>How far off the gauge centre the probe may start: each first touch searches this much further.</source>
        <translation>Насколько далеко от центра кольца может стоять датчик в начале: каждое первое касание ищет на столько дальше.</translation>
    </message>
    <message>
        <source>Delay-stability test program</source>
        <translation>Программа испытания стабильности задержки</translation>
    </message>
    <message>
        <source>Along one axis and direction: a locating touch, then the repeats at each feed, each from far enough out to touch at full speed, with a rapid retract between touches. Every move is incremental from where the probe stands. Save the plan with the program: &quot;Import machine log…&quot; needs it.</source>
        <translation>Вдоль одной оси в одном направлении: касание для поиска поверхности, затем повторы на каждой подаче, каждое с достаточного расстояния, чтобы касаться на полной скорости, с ускоренным отводом между касаниями. Все перемещения в приращениях от текущего положения датчика. Сохраните план вместе с программой: он нужен для «Импорт журнала ЧПУ…».</translation>
    </message>
    <message>
        <source>Axis and direction</source>
        <translation>Ось и направление</translation>
    </message>
    <message>
        <source>The direction of travel of the touches. One per program: the control cannot jog to another surface at a pause; paste the imports of several programs together.</source>
        <translation>Направление движения при касаниях. Одно на программу: на паузе ЧПУ не позволяет переместиться к другой поверхности; вставьте импорт нескольких программ вместе.</translation>
    </message>
    <message>
        <source>Feeds</source>
        <translation>Подачи</translation>
    </message>
    <message>
        <source>The feeds of the touches, %1, separated by semicolons or spaces; at least two.</source>
        <translation>Подачи касаний, %1, через точку с запятой или пробел; не меньше двух.</translation>
    </message>
    <message>
        <source>Touches per feed</source>
        <translation>Касаний на подачу</translation>
    </message>
    <message>
        <source>Start margin</source>
        <translation>Запас до старта</translation>
    </message>
    <message>
        <source>Each touch starts this much farther out than the distance the axis needs to reach its feed.</source>
        <translation>Каждое касание начинается на столько дальше расстояния, нужного оси для разгона до его подачи.</translation>
    </message>
    <message>
        <source>Start at most</source>
        <translation>Старт не дальше</translation>
    </message>
    <message>
        <source>The probe stands at most this far from the surface when the program starts; the locating touch searches this far.</source>
        <translation>При запуске программы датчик стоит от поверхности не дальше этого; касание поиска ищет на это расстояние.</translation>
    </message>
    <message>
        <source>Control</source>
        <translation>ЧПУ</translation>
    </message>
    <message>
        <source>The control&apos;s G-code dialect.</source>
        <translation>Диалект G-кода ЧПУ.</translation>
    </message>
    <message>
        <source>Program</source>
        <translation>Программа</translation>
    </message>
    <message>
        <source>Save program…</source>
        <translation>Сохранить программу…</translation>
    </message>
    <message>
        <source>Writes the program and, beside it, its plan (NAME.plan.json), which the import of the machine&apos;s log needs.</source>
        <translation>Записывает программу и рядом с ней её план (ИМЯ.plan.json), который нужен для импорта журнала ЧПУ.</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>Закрыть</translation>
    </message>
    <message>
        <source>%1: “%2” are not numbers separated by semicolons or spaces</source>
        <extracomment>%1 the label of the feeds box, %2 what it holds</extracomment>
        <translation>%1: «%2» — не числа через точку с запятой или пробел</translation>
    </message>
    <message>
        <source>%1 could not be written: %2</source>
        <translation>Не удалось записать %1: %2</translation>
    </message>
    <message>
        <source>Saved %1 and its plan %2</source>
        <extracomment>%1 the program&apos;s file, %2 its plan&apos;s</extracomment>
        <translation>Сохранено: %1 и его план %2</translation>
    </message>
    <message>
        <source>%1 programs (*.%2);;All files (*)</source>
        <extracomment>%1 the control (&quot;LinuxCNC&quot;), %2 the program&apos;s extension (&quot;ngc&quot;)</extracomment>
        <translation>Программы %1 (*.%2);;Все файлы (*)</translation>
    </message>
    <message>
        <source>Save program</source>
        <translation>Сохранение программы</translation>
    </message>
    <message>
        <source>No program: the options are refused (see the message).</source>
        <translation>Программы нет: параметры отклонены (см. сообщение).</translation>
    </message>
    <message>
        <source>Spindle to 180°</source>
        <translation>Поворот шпинделя на 180°</translation>
    </message>
    <message>
        <source>your control&apos;s block, from its manual</source>
        <translation>кадр вашей системы ЧПУ, из её руководства</translation>
    </message>
    <message>
        <source>The block your control turns the spindle to 180° with. The Fanuc-type programs need it: M19 with an angle differs by maker and machine, and ProbeCycle does not guess it (the CLI&apos;s --orient-180).</source>
        <translation>Кадр, которым ваша система ЧПУ поворачивает шпиндель на 180°. Он нужен программам типа Fanuc: M19 с углом различается у производителей и станков, и ProbeCycle его не угадывает (в CLI — --orient-180).</translation>
    </message>
    <message>
        <source>Tuned cycle program</source>
        <translation>Программа настроенного цикла</translation>
    </message>
    <message>
        <source>The direction of travel of the touch.</source>
        <translation>Направление движения при касании.</translation>
    </message>
    <message>
        <source>The axis the two walls are touched along, X or Y (both directions, + first).</source>
        <translation>Ось, вдоль которой касаются обеих сторон, X или Y (в обоих направлениях, сначала +).</translation>
    </message>
    <message>
        <source>Not used: a bore or boss is touched at X+, X-, Y+ and Y-.</source>
        <translation>Не используется: отверстия и бобышки касаются в X+, X-, Y+ и Y-.</translation>
    </message>
    <message>
        <source>The scenario&apos;s cycle on a surface, as plain probing moves: its strategy, feeds, backoff and start distance, the values you tuned here, not a maker&apos;s cycle call. The probe stands at the start distance in front of the surface. Every move is incremental from where the probe stands. Every move runs at a feed: prove it out at reduced feed override with the probe clear of the part.</source>
        <translation>Цикл сценария на поверхности в виде простых измерительных перемещений: его стратегия, подачи, отвод и начальное расстояние — значения, настроенные здесь, а не вызов цикла производителя. Датчик стоит на начальном расстоянии перед поверхностью. Каждое перемещение задано в приращениях от текущего положения датчика. Все перемещения идут на подаче: проверьте программу на пониженной коррекции подачи, с датчиком вдали от детали.</translation>
    </message>
    <message>
        <source>The scenario&apos;s cycle on its feature, as plain probing moves: its strategy, feeds, backoff and start distance, the values you tuned here, not a maker&apos;s cycle call. The probe starts at the feature&apos;s centre (over it for a boss or web) and every move toward the part is protected: a touch on the way is an obstruction. Every move is incremental from where the probe stands. Prove it out at reduced feed override (a boss&apos;s or web&apos;s lifts are rapids: reduced rapid override too) with the probe clear of the part.</source>
        <translation>Цикл сценария на его элементе в виде простых измерительных перемещений: его стратегия, подачи, отвод и начальное расстояние — значения, настроенные здесь, а не вызов цикла производителя. Датчик начинает в центре элемента (над ним — для бобышки или стенки), и каждое перемещение к детали защищённое: касание на пути означает препятствие. Каждое перемещение задано в приращениях от текущего положения датчика. Проверьте программу на пониженной коррекции подачи (подъёмы над бобышкой или стенкой идут ускоренным ходом: и на пониженной коррекции ускоренного хода), с датчиком вдали от детали.</translation>
    </message>
    <message>
        <source>Probe input</source>
        <translation>Вход щупа</translation>
    </message>
    <message>
        <source>1, rising edge</source>
        <translation>1, передний фронт</translation>
    </message>
    <message>
        <source>1, falling edge</source>
        <translation>1, задний фронт</translation>
    </message>
    <message>
        <source>2, rising edge</source>
        <translation>2, передний фронт</translation>
    </message>
    <message>
        <source>2, falling edge</source>
        <translation>2, задний фронт</translation>
    </message>
    <message>
        <source>Which probe input the measuring moves use (Siemens: MEAS=1, -1, 2 or -2), as the machine&apos;s builder wired it: falling edge for a probe whose signal falls when it triggers; the CLI&apos;s --probe-input.</source>
        <translation>Какой вход щупа используют измерительные перемещения (Siemens: MEAS=1, -1, 2 или -2), как его подключил производитель станка: задний фронт — для щупа, сигнал которого спадает при срабатывании; в CLI — --probe-input.</translation>
    </message>
</context>
<context>
    <name>probecycle::ui::QuantityEdit</name>
    <message>
        <source>Range: %1 to %2 %3</source>
        <translation>Диапазон: от %1 до %2 %3</translation>
    </message>
</context>
<context>
    <name>probecycle::ui::Readouts</name>
    <message>
        <source>Cycle time</source>
        <translation>Время цикла</translation>
    </message>
    <message>
        <source>Overtravel</source>
        <translation>Перебег</translation>
    </message>
    <message>
        <source>Trigger speed</source>
        <translation>Скорость срабатывания</translation>
    </message>
    <message>
        <source>Uncertainty (k = 2)</source>
        <translation>Неопределённость (k = 2)</translation>
    </message>
    <message>
        <source>Recommended backoff</source>
        <translation>Рекомендуемый отвод</translation>
    </message>
    <message>
        <source>Knee of the curve</source>
        <translation>Точка излома</translation>
    </message>
    <message>
        <source>Worst distance beyond the surface where the axis stops: pretravel + trigger speed × (interface + controller + full scan period) + braking distance.</source>
        <translation>Наибольшее расстояние за поверхностью, где останавливается ось: предход + скорость срабатывания × (интерфейс + ЧПУ + полный период опроса) + тормозной путь.</translation>
    </message>
    <message>
        <source>Speed when the measuring touch triggers; lower than programmed if the touch happens while accelerating.</source>
        <translation>Скорость при срабатывании измерительного касания; ниже запрограммированной, если касание происходит во время разгона.</translation>
    </message>
    <message>
        <source>invalid scenario</source>
        <translation>сценарий недопустим</translation>
    </message>
    <message>
        <source>target %1</source>
        <translation>цель %1</translation>
    </message>
    <message>
        <source>set %1</source>
        <translation>задано %1</translation>
    </message>
    <message>
        <source>for two-touch</source>
        <translation>для двукратного касания</translation>
    </message>
    <message>
        <source>cycle %1</source>
        <translation>цикл %1</translation>
    </message>
    <message>
        <source>Δ %1 vs baseline</source>
        <translation>Δ %1 к базе</translation>
    </message>
    <message>
        <source>%1 % of %2</source>
        <translation>%1 % от %2</translation>
    </message>
    <message>
        <source>as programmed</source>
        <translation>как задано</translation>
    </message>
    <message>
        <source>%1 % of %2, 2nd touch</source>
        <translation>%1 % от %2, второе касание</translation>
    </message>
    <message>
        <source>Total time of the probing cycle, all touches and moves. &quot;Invalid&quot; when the cycle cannot run as set (backoff too small, overtravel over the probe&apos;s limit): then it has no cycle time to compare.</source>
        <translation>Полное время цикла измерения со всеми касаниями и перемещениями. «Недопустим», когда цикл не может выполняться так, как задан (отвод слишком мал, перебег выше предела датчика): тогда сравнивать нечего.</translation>
    </message>
    <message>
        <source>The lowest probing feed whose cycle time is within the knee tolerance (1 % by default) of the best, among the valid cycles (overtravel under the probe&apos;s limit): faster buys almost no time.</source>
        <translation>Наименьшая подача поиска, время цикла на которой хуже лучшего не более чем на допуск точки излома (по умолчанию 1 %), среди допустимых циклов (перебег ниже предела датчика): быстрее почти не выигрывает времени.</translation>
    </message>
    <message>
        <source>Invalid</source>
        <translation>Недопустим</translation>
    </message>
    <message>
        <source>Two-touch: from the backoff&apos;s reference (where the probe stopped, or the recorded trigger position) the larger of the reseat distance and the distance to reach the measuring feed. Less risks a probe that has not reseated; more is approached again at the slow measuring feed.</source>
        <translation>Двукратное касание: от точки отсчёта отвода (точки остановки или записанной точки срабатывания) — большее из пути восстановления датчика и пути разгона до измерительной подачи. Меньше — датчик может не вернуться; больше — лишний путь проходится на медленной подаче.</translation>
    </message>
    <message>
        <source>At %1 % feed override the probe stops %2 past the surface: %3 % of the probe&apos;s %4 limit. Every overtravel check holds at that override (Highest feed override).</source>
        <translation>При коррекции подачи %1 % щуп останавливается на %2 за поверхностью: %3 % от предела щупа %4. Все проверки перебега выполняются при этой коррекции (Наибольшая коррекция подачи).</translation>
    </message>
    <message>
        <source>%1 % of limit at %2 %, 2nd touch</source>
        <translation>%1 % при %2 %, 2-е кас.</translation>
    </message>
    <message>
        <source>%1 % of limit at %2 %</source>
        <translation>%1 % при %2 %</translation>
    </message>
    <message>
        <source>Expanded (k = 2) uncertainty of the measured point: the trigger&apos;s part (the scan-period range and the probe&apos;s repeatability, averaged over repeats) combined with the probe&apos;s lobing, the calibration artefact, the machine&apos;s repeatability and the thermal drift. The value&apos;s tooltip shows the budget.</source>
        <translation>Расширенная неопределённость (k = 2) измеряемой точки: доля срабатывания (разброс периода опроса и повторяемость датчика, усреднённые по повторам) вместе с лепестковостью датчика, эталоном калибровки, повторяемостью станка и температурным дрейфом. Подсказка значения показывает бюджет.</translation>
    </message>
    <message>
        <source>trigger %1</source>
        <translation>срабатывание %1</translation>
    </message>
    <message>
        <source>&lt;p&gt;The measurement&apos;s uncertainty budget: each term&apos;s standard uncertainty, combined as the root sum of squares and expanded with k = 2. Set the terms under Machine and Probe.&lt;/p&gt;</source>
        <translation>&lt;p&gt;Бюджет неопределённости измерения: стандартная неопределённость каждого члена, сложенная как корень из суммы квадратов и расширенная с k = 2. Члены задаются в разделах «Станок» и «Датчик».&lt;/p&gt;</translation>
    </message>
    <message>
        <source>%1 % of programmed</source>
        <translation>%1 % от заданной</translation>
    </message>
</context>
<context>
    <name>probecycle::ui::ReportDetailsDialog</name>
    <message>
        <source>Customer</source>
        <translation>Заказчик</translation>
    </message>
    <message>
        <source>Machine</source>
        <translation>Станок</translation>
    </message>
    <message>
        <source>Part</source>
        <translation>Деталь</translation>
    </message>
    <message>
        <source>Author</source>
        <translation>Автор</translation>
    </message>
    <message>
        <source>Notes</source>
        <translation>Примечания</translation>
    </message>
    <message>
        <source>Report Details</source>
        <translation>Данные отчёта</translation>
    </message>
    <message>
        <source>Shown at the top of the PDF report&apos;s first page, with the date and the program&apos;s version. Saved in the project file.</source>
        <translation>Выводятся в начале первой страницы отчёта PDF вместе с датой и версией программы. Сохраняются в файле проекта.</translation>
    </message>
</context>
<context>
    <name>probecycle::ui::StatusText</name>
    <message>
        <source>Unexpected error: %1</source>
        <extracomment>an exception the window does not expect (out of memory...); %1 its English text</extracomment>
        <translation>Непредвиденная ошибка: %1</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>Сохранено: %1</translation>
    </message>
</context>
<context>
    <name>probecycle::ui::WarningsPanel</name>
    <message>
        <source>No warnings: the cycle is within the probe&apos;s limits.</source>
        <translation>Предупреждений нет: цикл в пределах возможностей датчика.</translation>
    </message>
    <message>
        <source>Invalid scenario</source>
        <translation>Недопустимый сценарий</translation>
    </message>
    <message>
        <source>Set backoff to %1</source>
        <translation>Отвод %1</translation>
    </message>
    <message>
        <source>Drop feed to the knee, %1</source>
        <translation>Подачу до излома, %1</translation>
    </message>
    <message>
        <source>Start %1 out</source>
        <translation>Начало за %1</translation>
    </message>
    <message>
        <source>Drop feed to %1</source>
        <translation>Снизить подачу до %1</translation>
    </message>
    <message>
        <source>Error</source>
        <translation>Ошибка</translation>
    </message>
    <message>
        <source>Warning</source>
        <translation>Предупреждение</translation>
    </message>
    <message>
        <source>Note</source>
        <translation>Примечание</translation>
    </message>
    <message>
        <source>Search %1 past the surface</source>
        <translation>Поиск на %1 за поверхность</translation>
    </message>
    <message>
        <source>Position at %1</source>
        <translation>Позиционирование на %1</translation>
    </message>
    <message>
        <source>%1, backoff %2</source>
        <extracomment>%1 what the fix sets (&quot;Start 15.680 mm out&quot;), %2 the backoff it needs with it</extracomment>
        <translation>%1, отвод %2</translation>
    </message>
</context>
</TS>
