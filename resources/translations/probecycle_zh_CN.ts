<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="zh_CN">
<context>
    <name>Calibration</name>
    <message>
        <source>%1 is not allowed: the spindle orientation is 0 or 180</source>
        <translation>不允许 %1：主轴定向只能为 0 或 180</translation>
    </message>
    <message>
        <source>no points; a ring needs 3 or more per orientation</source>
        <translation>没有测点；环规每个定向需要 3 个或更多测点</translation>
    </message>
    <message>
        <source>orientation %1 has only %2 point (%3); a circle needs 3 or more per orientation (typically 4: X+, X-, Y+, Y-)</source>
        <translation>定向 %1 只有 %2 个测点（%3）；拟合圆每个定向需要 3 个或更多测点（通常为 4 个：X+、X-、Y+、Y-）</translation>
    </message>
    <message>
        <source>orientation %1 has only %2 points (%3); a circle needs 3 or more per orientation (typically 4: X+, X-, Y+, Y-)</source>
        <translation>定向 %1 只有 %2 个测点（%3）；拟合圆每个定向需要 3 个或更多测点（通常为 4 个：X+、X-、Y+、Y-）</translation>
    </message>
    <message>
        <source>the points at orientation %1 (%2) lie on a line or repeat: no circle through them; touch 3 or more distinct points around the bore</source>
        <translation>定向 %1 的测点（%2）共线或重复：无法通过它们拟合圆；请在孔周围触测 3 个或更多不同的点</translation>
    </message>
    <message>
        <source>the points at %1 cover only %2 of the bore (all on one side): the centre across that side is poorly determined; touch around the whole bore (X+, X-, Y+, Y-)</source>
        <translation>%1 的测点只覆盖孔的 %2（全部在一侧）：中心在该侧方向上确定不准；请沿整个孔触测（X+、X-、Y+、Y-）</translation>
    </message>
    <message>
        <source>3 points at %1: the circle passes through them exactly, so the residual shows nothing; a fourth point checks the touches</source>
        <translation>%1 下只有 3 个测点：圆恰好通过这些点，因此残差说明不了什么；第四个点可以校核触测</translation>
    </message>
    <message>
        <source>stylus runout %1 (x %2, y %3) exceeds %4: set the stylus on centre, and check that the spindle orients repeatably</source>
        <translation>测针跳动 %1（x %2，y %3）超过 %4：请将测针调至中心，并检查主轴定向是否可重复</translation>
    </message>
    <message>
        <source>only orientation %1 given: no runout. The centre is that of the %1 circle and is off the gauge centre by the stylus runout; touch the same points at %2 to separate the two</source>
        <translation>只给出了定向 %1：无法求跳动。中心为 %1 圆的中心，与环规中心相差一个测针跳动；请在 %2 下触测相同的点，以将二者分开</translation>
    </message>
    <message>
        <source>a point is %1 off the fitted circle (limit %2): clean the gauge and the stylus, check the gauge is clamped, and repeat the touch</source>
        <translation>有一个测点偏离拟合圆 %1（极限 %2）：请清洁环规和测针，检查环规是否夹紧，然后重新触测</translation>
    </message>
    <message>
        <source>the point on line %1 is %2 off the fitted circle (limit %3): clean the gauge and the stylus, check the gauge is clamped, and repeat the touch</source>
        <translation>第 %1 行的测点偏离拟合圆 %2（极限 %3）：请清洁环规和测针，检查环规是否夹紧，然后重新触测</translation>
    </message>
    <message>
        <source>the touches lie on a circle of radius %1, not inside the gauge of radius %2 (diameter %3): the effective ball radius would not be positive; check the gauge diameter</source>
        <translation>触测点位于半径 %1 的圆上，不在半径 %2（直径 %3）的环规之内：有效测球半径将不为正；请检查环规直径</translation>
    </message>
    <message>
        <source>no trigger Z given; touch the surface at least once</source>
        <translation>未给出触发 Z；请至少触测表面一次</translation>
    </message>
    <message>
        <source>effective length %1 is not positive: with Z up, the trigger Z plus the active length offset must lie above the surface Z</source>
        <translation>有效长度 %1 不为正：Z 轴向上为正时，触发 Z 加上当前长度补偿必须高于表面 Z</translation>
    </message>
    <message>
        <source>the effective length differs from the nominal %1 by %2 (limit %3): check the nominal, the surface Z and the stylus</source>
        <translation>有效长度与名义长度 %1 相差 %2（极限 %3）：请检查名义长度、表面 Z 和测针</translation>
    </message>
</context>
<context>
    <name>Comparison</name>
    <message>
        <source>a surface needs %1 points or more; got %2</source>
        <translation>拟合曲面需要 %1 个或更多测点；实际为 %2 个</translation>
    </message>
    <message>
        <source>the points lie on a line: they span no surface</source>
        <translation>测点共线：无法构成曲面</translation>
    </message>
    <message>
        <source>the surface fit has no unique solution for these points</source>
        <translation>对这些测点的曲面拟合没有唯一解</translation>
    </message>
    <message>
        <source>face %1 at C = %2: the touches lie on a line and define no plane; touch the face at points spread over it</source>
        <translation>C = %2 时的面 %1：触测点共线，无法确定平面；请在整个面上分散触测</translation>
    </message>
    <message>
        <source>block at C = %1: the three faces&apos; planes do not meet in one point (two of them are parallel); touch three faces of a corner</source>
        <translation>C = %1 时的试块：三个面的平面不交于一点（其中两个平行）；请触测构成同一个角的三个面</translation>
    </message>
    <message>
        <source>face %1 at C = %2: the touches nearly lie on a line (spread ratio %3); the face&apos;s tilt about that line is poorly known</source>
        <translation>C = %2 时的面 %1：触测点近乎共线（分布比 %3）；该面绕这条直线的倾斜确定不准</translation>
    </message>
    <message>
        <source>face %1 at C = %2: a touch lies %3 off the face&apos;s plane (above %4); a chip, a burr or a bad touch?</source>
        <translation>C = %2 时的面 %1：有一个触测点偏离该面的平面 %3（超过 %4）；是切屑、毛刺还是触测不良？</translation>
    </message>
    <message>
        <source>faces %1 and %2 at C = %3 meet at %4 (below %5): the corner is poorly defined</source>
        <translation>C = %3 时面 %1 与面 %2 的夹角为 %4（小于 %5）：角点确定不准</translation>
    </message>
    <message>
        <source>a face has only 3 touches: its plane passes through them, so the C-axis errors&apos; uncertainty is unknown; touch each face 6 times</source>
        <translation>有一个面只有 3 个触测点：平面恰好通过这些点，因此 C轴误差的不确定度未知；请在每个面上触测 6 次</translation>
    </message>
    <message>
        <source>%1 measured points for %2 plan points; one measured point per plan point is needed</source>
        <translation>%2 个计划点对应 %1 个测得点；每个计划点需要一个测得点</translation>
    </message>
    <message>
        <source>the block is needed at C = 0 and after the turn; only one is given</source>
        <translation>需要 C = 0 时和旋转后的试块数据；只给出了其中一组</translation>
    </message>
    <message>
        <source>the surface through the %1 leaves residuals up to %2 (RMS %3, above %4): the plan may be too sparse for the part&apos;s form, or a point is wrong</source>
        <translation>通过%1的曲面残差最大达 %2（RMS %3，超过 %4）：检测计划的测点相对零件形状可能过于稀疏，或有测点错误</translation>
    </message>
    <message>
        <source>reference&apos;s CMM points</source>
        <translation>参考件的三坐标测量机测点</translation>
    </message>
    <message>
        <source>plan&apos;s nominal points</source>
        <translation>检测计划的名义点</translation>
    </message>
    <message>
        <source>calibrated reference points</source>
        <translation>标定后的参考件测点</translation>
    </message>
    <message>
        <source>%1 points project onto the edge of a fitted surface, not square onto it (points %2): their results are less sure</source>
        <translation>有 %1 个测点投影到拟合曲面的边缘，而非垂直投影到曲面上（测点 %2）：其结果可靠性较低</translation>
    </message>
    <message>
        <source>%1 measured points lie more than %2 from their plan points (points %3): are the files in the plan&apos;s order, and the C axis&apos;s position and angle right?</source>
        <translation>有 %1 个测得点距其计划点超过 %2（测点 %3）：文件是否按检测计划的顺序排列？C轴的位置和角度是否正确？</translation>
    </message>
    <message>
        <source>at %1 points the result differs from its first-order estimate by more than %2 (points %3): the surfaces do not follow the points there</source>
        <translation>有 %1 个测点的结果与其一阶估计相差超过 %2（测点 %3）：曲面在这些位置未能贴合测点</translation>
    </message>
    <message>
        <source>the C-axis errors&apos; uncertainty reaches %1 on the part (above %2): touch the block more often or on larger faces, or judge whether the correction helps</source>
        <translation>C轴误差的不确定度在零件上达到 %1（超过 %2）：请增加试块的触测次数或在更大的面上触测，或判断该修正是否有益</translation>
    </message>
    <message>
        <source>only PTMEAS/CART,x,y,z,i,j,k is read; got &apos;%1&apos;</source>
        <translation>只读取 PTMEAS/CART,x,y,z,i,j,k；实际为“%1”</translation>
    </message>
    <message>
        <source>PTMEAS/CART has %1 numbers; the plan needs 6 (x, y, z, i, j, k)</source>
        <translation>PTMEAS/CART 含 %1 个数值；检测计划需要 6 个（x, y, z, i, j, k）</translation>
    </message>
    <message>
        <source>PTMEAS/CART has %1 numbers; allowed: 3 (x, y, z) or 6 (x, y, z, i, j, k)</source>
        <translation>PTMEAS/CART 含 %1 个数值；允许：3 个（x, y, z）或 6 个（x, y, z, i, j, k）</translation>
    </message>
    <message>
        <source>the normal (i, j, k) has length %1; allowed: a unit vector, length 1 within %2</source>
        <translation>法向 (i, j, k) 的长度为 %1；允许：单位矢量，长度为 1，偏差不超过 %2</translation>
    </message>
    <message>
        <source>point %1 has no plan point: the file has %2 points, the plan %3</source>
        <translation>测点 %1 没有对应的计划点：文件有 %2 个测点，检测计划有 %3 个</translation>
    </message>
    <message>
        <source>the file ends after %1 points; the plan has %2 (one measured point per plan point, in the plan&apos;s order)</source>
        <translation>文件在 %1 个测点后结束；检测计划有 %2 个点（每个计划点一个测得点，按检测计划的顺序）</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a face; allowed: A, B, C</source>
        <translation>“%1”不是面；允许：A、B、C</translation>
    </message>
    <message>
        <source>touches on face %1: %2; each face needs %3 or more (typically 6)</source>
        <translation>面 %1 上的触测点数：%2；每个面需要 %3 个或更多（通常为 6 个）</translation>
    </message>
    <message>
        <source>no block touched: the C axis is taken as exact and its errors stay in the result; %1 from the axis, every 10 µrad of tilt or turn moves a point by %2</source>
        <translation>未触测试块：C轴视为无误差，其误差保留在结果中；在距轴线 %1 处，每 10 µrad 的倾斜或转角误差使测点偏移 %2</translation>
    </message>
    <message>
        <source>a comparison needs %2 points or more; got %1</source>
        <translation>比对测量需要 %2 个或更多测点；实际为 %1 个</translation>
    </message>
    <message>
        <source>this point lies %1 from its plan point (plan line %2); allowed: within the plan&apos;s extent, %3; the points follow the plan&apos;s order, one per plan point</source>
        <translation>此点距其计划点（计划第 %2 行）%1；允许：在计划范围 %3 之内；各点按计划顺序排列，每个计划点一个</translation>
    </message>
    <message>
        <source>this point lies %1 from its plan point (plan line %2) but %3 from the plan point of line %4: the points must follow the plan&apos;s order, one per plan point</source>
        <translation>此点距其计划点（计划第 %2 行）%1，但距第 %4 行的计划点仅 %3：各点必须按计划顺序排列，每个计划点一个</translation>
    </message>
</context>
<context>
    <name>CsvError</name>
    <message>
        <source>line %1: %2</source>
        <translation>第 %1 行：%2</translation>
    </message>
    <message>
        <source>line %1, column %2: %3</source>
        <translation>第 %1 行，%2 列：%3</translation>
    </message>
    <message>
        <source>missing column &apos;%1&apos;; the header must name the columns %2 (comma-separated)</source>
        <translation>缺少列“%1”；表头必须列出 %2 这些列（以逗号分隔）</translation>
    </message>
    <message>
        <source>column &apos;%1&apos; appears twice in the header</source>
        <translation>列“%1”在表头中出现了两次</translation>
    </message>
    <message>
        <source>%1 fields, but the header has %2 (%3)</source>
        <translation>有 %1 个字段，但表头有 %2 个（%3）</translation>
    </message>
    <message>
        <source>the file is empty; expected a header line %1 and one line per touch</source>
        <translation>文件为空；应有表头行 %1，且每次触测一行</translation>
    </message>
    <message>
        <source>no data after the header; expected one line per touch under %1</source>
        <translation>表头之后没有数据；%1 之下应每次触测一行</translation>
    </message>
    <message>
        <source>empty; expected a number</source>
        <translation>为空；应为数值</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a number (use &apos;.&apos; as the decimal point)</source>
        <translation>“%1”不是数值（小数点请用“.”）</translation>
    </message>
    <message>
        <source>no line</source>
        <translation>无行</translation>
    </message>
    <message>
        <source>line %1</source>
        <translation>第 %1 行</translation>
    </message>
    <message>
        <source>lines %1</source>
        <translation>第 %1 行</translation>
    </message>
    <message>
        <source>out of range: a coordinate within +-%1 mm</source>
        <translation>超出范围：坐标应在 ±%1 mm 以内</translation>
    </message>
</context>
<context>
    <name>DelayFit</name>
    <message>
        <source>%1, %2</source>
        <extracomment>a list of feeds, &quot;500 mm/min, 900 mm/min&quot;; %2 is the rest of the list</extracomment>
        <translation>%1、%2</translation>
    </message>
    <message>
        <source>%1: only %2 feeds; a line through two feeds cannot show whether the delay is constant: touch at 3 or more</source>
        <translation>%1：只有 %2 个进给率；通过两个进给率的直线无法显示延迟是否恒定：请在 3 个或更多进给率下触测</translation>
    </message>
    <message>
        <source>%1: the fitted delay is negative (%2): the recorded position moves against the travel as the feed rises; check the direction column (+1/-1 is the direction of travel)</source>
        <translation>%1：拟合的延迟为负（%2）：进给率升高时，记录的位置逆行程方向移动；请检查 direction 列（+1/-1 为行程方向）</translation>
    </message>
    <message>
        <source>%1: one touch only at %2: no scatter there; repeat each touch (5 or more) to see the stability</source>
        <translation>%1：在 %2 下只有一次触测：那里看不出分散；请重复每次触测（5 次或更多）以查看稳定性</translation>
    </message>
    <message>
        <source>%1: at %2 the touches spread over %3 (%4 of travel), more than %5x what the other feeds predict (%6): the delay is not stable there; repeat the touches and check the input and the controller load</source>
        <translation>%1：在 %2 下触测分散达 %3（相当于 %4 的行程），超过其他进给率预测值（%6）的 %5 倍：该处延迟不稳定；请重复触测，并检查输入信号和控制器负载</translation>
    </message>
    <message>
        <source>%1: the residuals curve: the touches depart from the line by up to %2; the delay is not constant but goes from %3 at %4 to %5 at %6; a correction with one delay is right at one feed only</source>
        <translation>%1：残差呈曲线：触测点偏离直线最多 %2；延迟并不恒定，而是从 %4 下的 %3 变为 %6 下的 %5；用单一延迟的补偿只在一个进给率下正确</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not an axis name (a letter, e.g. X, Y, Z)</source>
        <translation>“%1”不是轴名（应为字母，如 X、Y、Z）</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not allowed: +1 or -1, the direction of travel</source>
        <translation>不允许“%1”：应为 +1 或 -1，即行程方向</translation>
    </message>
    <message>
        <source>%1 is out of range: (0, %2] mm/min</source>
        <translation>%1 超出范围：(0, %2] mm/min</translation>
    </message>
    <message>
        <source>%1: only one touch (%2, %3); the delay is the slope over feeds: touch at 2 or more feeds, 3 or more to check that it is constant</source>
        <translation>%1：只有一次触测（%2，%3）；延迟是随进给率变化的斜率：请在 2 个或更多进给率下触测，3 个或更多可检验其是否恒定</translation>
    </message>
    <message>
        <source>%1: all %2 touches are at one feed (%3, %4); the delay is the slope over feeds: touch at 2 or more feeds, 3 or more to check that it is constant</source>
        <translation>%1：全部 %2 次触测都在同一进给率下（%3，%4）；延迟是随进给率变化的斜率：请在 2 个或更多进给率下触测，3 个或更多可检验其是否恒定</translation>
    </message>
    <message>
        <source>the fit has no groups of touches</source>
        <translation>拟合中没有触测组</translation>
    </message>
    <message>
        <source>the group chosen</source>
        <translation>所选的组</translation>
    </message>
    <message>
        <source>got &apos;%1&apos;; allowed: a group of the file (%2)</source>
        <translation>值为“%1”；允许：文件中的组（%2）</translation>
    </message>
    <message>
        <source>the only group</source>
        <translation>唯一的组</translation>
    </message>
    <message>
        <source>the longest delay of %1 groups (the safe side for overtravel); choose one to override</source>
        <translation>%1 个组中延迟最长者（对过行程偏于安全）；可选择一个组来替代</translation>
    </message>
    <message>
        <source>the fitted delay of %1, %2, is shorter than the scenario&apos;s probe.interface_delay_s + half of machine.scan_period_s (%3): the controller latency would be negative; check those keys (or machine.latched_input) in the scenario</source>
        <translation>%1 的拟合延迟 %2 短于场景中 probe.interface_delay_s 加 machine.scan_period_s 的一半（%3）：控制器延迟将为负；请检查场景中的这些键（或 machine.latched_input）</translation>
    </message>
    <message>
        <source>the fitted delay of %1, %2, is negative: the input is latched, so it would be the probe&apos;s interface delay; check the touches</source>
        <translation>%1 的拟合延迟 %2 为负：输入为锁存输入，该值将作为测头接口延迟；请检查触测数据</translation>
    </message>
</context>
<context>
    <name>Feature</name>
    <message>
        <source>surface</source>
        <translation>平面</translation>
    </message>
    <message>
        <source>web</source>
        <translation>凸台</translation>
    </message>
    <message>
        <source>pocket</source>
        <translation>槽</translation>
    </message>
    <message>
        <source>bore</source>
        <translation>孔</translation>
    </message>
    <message>
        <source>boss</source>
        <translation>圆柱</translation>
    </message>
</context>
<context>
    <name>FieldError</name>
    <message>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <source>%1: got %2; allowed: %3</source>
        <translation>%1：值为 %2；允许：%3</translation>
    </message>
    <message>
        <source>a number from %1 to %2 %3</source>
        <translation>%1 到 %2 %3 之间的数值</translation>
    </message>
    <message>
        <source>one of %1</source>
        <translation>以下之一：%1</translation>
    </message>
    <message>
        <source>true or false</source>
        <translation>true 或 false</translation>
    </message>
    <message>
        <source>unknown key; allowed in %1: %2</source>
        <translation>未知的键；%1 中允许：%2</translation>
    </message>
    <message>
        <source>more than twice cycle.approach_mm (%1) for a %2</source>
        <translation>对于 %2，须大于 cycle.approach_mm 的两倍（%1）</translation>
    </message>
    <message>
        <source>malformed JSON: %1</source>
        <translation>JSON 格式错误：%1</translation>
    </message>
    <message>
        <source>a number out of range: %1</source>
        <translation>数值超出范围：%1</translation>
    </message>
    <message>
        <source>a JSON object with sections machine, probe, cycle</source>
        <translation>含 machine、probe、cycle 三部分的 JSON 对象</translation>
    </message>
    <message>
        <source>an object of keys</source>
        <translation>由键组成的对象</translation>
    </message>
    <message>
        <source>section.key=value</source>
        <translation>部分.键=值（section.key=value）</translation>
    </message>
    <message>
        <source>unknown key; sections are machine, probe, cycle</source>
        <translation>未知的键；部分为 machine、probe、cycle</translation>
    </message>
    <message>
        <source>a number in (%1, %2)</source>
        <translation>(%1, %2) 内的数值</translation>
    </message>
    <message>
        <source>a number in (%1, %2]</source>
        <translation>(%1, %2] 内的数值</translation>
    </message>
    <message>
        <source>a number in [%1, %2)</source>
        <translation>[%1, %2) 内的数值</translation>
    </message>
    <message>
        <source>a number in [%1, %2]</source>
        <translation>[%1, %2] 内的数值</translation>
    </message>
    <message>
        <source>+1 or -1</source>
        <translation>+1 或 -1</translation>
    </message>
    <message>
        <source>a counter wide enough that one cycle (%1 counts) moves it by less than half its range</source>
        <translation>位数足够的计数器：一个周期（%1 个计数）的变化小于其量程的一半</translation>
    </message>
    <message>
        <source>text without NUL bytes; one is at line %1, column %2</source>
        <translation>不含 NUL 字节的文本；第 %1 行第 %2 列有一个</translation>
    </message>
    <message>
        <source>at most %3 levels of nesting; line %1, column %2 opens one more</source>
        <translation>最多 %3 层嵌套；第 %1 行第 %2 列又打开了一层</translation>
    </message>
    <message>
        <source>a key with a name; line %1, column %2 has an empty key &quot;&quot;</source>
        <translation>有名称的键；第 %1 行第 %2 列是空键 &quot;&quot;</translation>
    </message>
    <message>
        <source>each key once per object; it is given at line %1 and again at line %2</source>
        <translation>每个对象中每个键只出现一次；它在第 %1 行给出，又在第 %2 行给出</translation>
    </message>
    <message>
        <source>%1: got %2... (%4 characters); allowed: %3</source>
        <translation>%1：值为 %2...（共 %4 个字符）；允许：%3</translation>
    </message>
    <message>
        <source>a number a double can hold (up to about 1.8e308); at line %1 it is out of range</source>
        <translation>双精度数能表示的数值（最大约 1.8e308）；第 %1 行的数值超出范围</translation>
    </message>
    <message>
        <source>unknown section; allowed: %1</source>
        <translation>未知的部分；允许：%1</translation>
    </message>
    <message>
        <source>a JSON object with the comparison&apos;s files and settings</source>
        <translation>含比较测量文件和设置的 JSON 对象</translation>
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
        <translation>文本形式的文件路径（为空表示无）</translation>
    </message>
    <message>
        <source>an unknown key; allowed: %1</source>
        <translation>未知的键；允许：%1</translation>
    </message>
    <message>
        <source>a number from %1 to %2</source>
        <translation>%1 到 %2 之间的数值</translation>
    </message>
    <message>
        <source>text</source>
        <translation>文本</translation>
    </message>
    <message>
        <source>a whole number from %1 to %2</source>
        <translation>%1 到 %2 之间的整数</translation>
    </message>
    <message>
        <source>&quot;probecycle-project&quot; (a ProbeCycle project)</source>
        <translation>&quot;probecycle-project&quot;（ProbeCycle 项目）</translation>
    </message>
    <message>
        <source>1 (a newer ProbeCycle wrote this file)</source>
        <translation>1（此文件由更新版本的 ProbeCycle 写入）</translation>
    </message>
    <message>
        <source>missing; a project holds a scenario</source>
        <translation>缺失；项目必须包含场景</translation>
    </message>
    <message>
        <source>from 2 to %1 different feeds</source>
        <translation>2 到 %1 个不同的进给率</translation>
    </message>
    <message>
        <source>one line of text, at most %1 characters</source>
        <translation>一行文本，最多 %1 个字符</translation>
    </message>
    <message>
        <source>true or false (true on a probe only)</source>
        <translation>true 或 false（仅触测可为 true）</translation>
    </message>
    <message>
        <source>&quot;probecycle-probing-plan&quot; (a plan that probecycle-cli program wrote)</source>
        <translation>&quot;probecycle-probing-plan&quot;（由 probecycle-cli program 写出的计划）</translation>
    </message>
    <message>
        <source>a list of at most 20000 steps</source>
        <translation>最多 20000 步的列表</translation>
    </message>
    <message>
        <source>no recorded probe; a plan needs one or more</source>
        <translation>没有记录的触测；计划至少需要一次</translation>
    </message>
    <message>
        <source>X+, X-, Y+ or Y- for a %1 (touched from both sides along X or Y)</source>
        <translation>对于 %1，须为 X+、X-、Y+ 或 Y-（沿 X 或 Y 从两侧触测）</translation>
    </message>
    <message>
        <source>at least %1 for a %2 (the probe moves over its wall between touches)</source>
        <translation>对于 %2，须至少为 %1（各次触测之间测头从其上方越过）</translation>
    </message>
    <message>
        <source>at most %1 for a %2&apos;s program (its moves from the centre to the touches&apos; starts are at most %3)</source>
        <translation>对于 %2 的程序，须至多为 %1（其从中心到各次触测起点的移动最长为 %3）</translation>
    </message>
    <message>
        <source>at least %1, the stop of the touch at %2 past its surface (a search that ends sooner is braking when it touches), or 0 for automatic</source>
        <translation>至少 %1，即 %2 下触测在表面之后的停止位置（更早结束的搜索在触碰时已在减速），或 0 表示自动</translation>
    </message>
    <message>
        <source>a feed at which an obstruction met by a protected move stops short of the probe&apos;s %1 limit (now %2 past it)</source>
        <translation>受保护移动碰到障碍物时能在测头 %1 极限之内停止的进给率（当前停在障碍物之后 %2）</translation>
    </message>
    <message>
        <source>less than %1, the %2&apos;s distance between stylus centres (cycle.feature_size_mm)</source>
        <translation>小于 %1，即%2的测针中心间距（cycle.feature_size_mm）</translation>
    </message>
    <message>
        <source>the whole number 1 (this ProbeCycle&apos;s project version)</source>
        <translation>整数 1（本 ProbeCycle 的项目版本）</translation>
    </message>
</context>
<context>
    <name>FileError</name>
    <message>
        <source>cannot write %1: %2</source>
        <translation>无法写入 %1：%2</translation>
    </message>
    <message>
        <source>cannot open %1: %2</source>
        <translation>无法打开 %1：%2</translation>
    </message>
    <message>
        <source>it is a directory</source>
        <translation>它是一个文件夹</translation>
    </message>
    <message>
        <source>it is not a regular file (a pipe, a device or a socket); ProbeCycle writes only regular files</source>
        <translation>它不是普通文件（而是管道、设备或套接字）；ProbeCycle 只写入普通文件</translation>
    </message>
    <message>
        <source>it is a symbolic link to a folder that does not exist</source>
        <translation>它是指向不存在的文件夹的符号链接</translation>
    </message>
    <message>
        <source>it has more than %1 bytes, the limit for an input file (%2 MiB)</source>
        <translation>它超过 %1 字节，即输入文件的上限（%2 MiB）</translation>
    </message>
    <message>
        <source>it has %1 bytes; the limit for an input file is %2 bytes (%3 MiB)</source>
        <translation>它有 %1 字节；输入文件的上限为 %2 字节（%3 MiB）</translation>
    </message>
    <message>
        <source>it is read-only; ProbeCycle does not replace a protected file</source>
        <translation>它是只读的；ProbeCycle 不会替换受保护的文件</translation>
    </message>
    <message>
        <source>the folder %1 cannot be written to (%2)</source>
        <translation>无法写入文件夹 %1（%2）</translation>
    </message>
    <message>
        <source>another output of this command goes there too (%1); give each output a file of its own</source>
        <translation>此命令的另一个输出也写到那里（%1）；请为每个输出指定各自的文件</translation>
    </message>
    <message>
        <source>it is not a folder; give a folder that does not exist yet, or one this command wrote before</source>
        <translation>它不是文件夹；请指定一个尚不存在的文件夹，或此命令以前写过的文件夹</translation>
    </message>
    <message>
        <source>its parent folder does not exist</source>
        <translation>它的上级文件夹不存在</translation>
    </message>
    <message>
        <source>the folder holds %1 entries other than the files this command writes (%2); give a new or empty folder</source>
        <translation>该文件夹中除本命令写入的文件外还有 %1 个条目（%2）；请指定新的或空的文件夹</translation>
    </message>
    <message>
        <source>its name is a Windows device&apos;s (CON, PRN, AUX, NUL, COM1-9, LPT1-9, with any extension); give another name</source>
        <translation>该名称是 Windows 设备名（CON、PRN、AUX、NUL、COM1-9、LPT1-9，扩展名不限）；请换一个名称</translation>
    </message>
</context>
<context>
    <name>LinuxCncIni</name>
    <message>
        <source>a decimal number</source>
        <translation>十进制数</translation>
    </message>
    <message>
        <source>missing section; expected %1 (for %2)</source>
        <translation>缺少该节；应包含 %1（用于 %2）</translation>
    </message>
    <message>
        <source>missing; expected %1 (for %2)</source>
        <translation>缺失；应为 %1（用于 %2）</translation>
    </message>
    <message>
        <source>no value; expected %1 (for %2)</source>
        <translation>没有值；应为 %1（用于 %2）</translation>
    </message>
    <message>
        <source>got %1; allowed: %2 (for %3)</source>
        <translation>值为 %1；允许：%2（用于 %3）</translation>
    </message>
    <message>
        <source>line %1: %2</source>
        <translation>第 %1 行：%2</translation>
    </message>
    <message>
        <source>[%1]: %2</source>
        <translation>[%1]：%2</translation>
    </message>
    <message>
        <source>[%1] %2: %3</source>
        <translation>[%1] %2：%3</translation>
    </message>
    <message>
        <source>[%1] %2, line %3: %4</source>
        <translation>[%1] %2，第 %3 行：%4</translation>
    </message>
    <message>
        <source>#INCLUDE is not followed; LinuxCNC writes the configuration with its includes to NAME.ini.expanded beside the INI file when it starts: read that file</source>
        <translation>不处理 #INCLUDE；LinuxCNC 启动时会把展开了所有包含文件的配置写入 INI 文件旁的 NAME.ini.expanded：请读取该文件</translation>
    </message>
    <message>
        <source>a whole number from %1 to %2 ns</source>
        <translation>%1 到 %2 ns 之间的整数</translation>
    </message>
    <message>
        <source>one of %1, or a number of units per mm from %2 to %3</source>
        <translation>以下之一：%1，或每毫米的单位数，从 %2 到 %3</translation>
    </message>
</context>
<context>
    <name>MachineLog</name>
    <message>
        <source>cannot read &apos;%1&apos;; expected %2</source>
        <translation>无法读取“%1”；应为 %2</translation>
    </message>
    <message>
        <source>the log ends after %1 of the plan&apos;s %2 probe positions: the program stopped early, a position was not recorded, or the log is from another plan; nothing imported</source>
        <translation>日志在计划的 %2 个触测位置中的第 %1 个之后结束：程序提前停止、某个位置未记录，或日志来自另一计划；未导入任何内容</translation>
    </message>
    <message>
        <source>a probe position more than the plan&apos;s %1: the program ran twice into one log, or the log is from another plan; nothing imported</source>
        <translation>触测位置多于计划的 %1 个：程序在同一日志中运行了两次，或日志来自另一计划；未导入任何内容</translation>
    </message>
    <message>
        <source>%1 moved %2 since line %3, but the plan moves only %4 between these probes: is the log from another plan? Nothing imported</source>
        <translation>%1 自第 %3 行起移动了 %2，但计划在这两次触测之间只移动 %4：日志是否来自另一计划？未导入任何内容</translation>
    </message>
    <message>
        <source>the log is from plan %1, the plan file is plan %2: give the plan the program was made from; nothing imported</source>
        <translation>日志来自计划 %1，计划文件为计划 %2：请提供生成该程序的计划；未导入任何内容</translation>
    </message>
    <message>
        <source>touch %1 where touch %2 was due: the log holds more than one run; nothing imported</source>
        <translation>应为第 %2 次触测处出现第 %1 次触测：日志包含多次运行；未导入任何内容</translation>
    </message>
    <message>
        <source>grbl raised &apos;%1&apos; (ALARM:5: the probe did not touch; ALARM:4: it was triggered before the move): the program stopped there; nothing imported</source>
        <translation>grbl 报出“%1”（ALARM:5：测头未触碰；ALARM:4：移动前已触发）：程序在此停止；未导入任何内容</translation>
    </message>
    <message>
        <source>the probe did not trigger (%1); nothing imported</source>
        <translation>测头未触发（%1）；未导入任何内容</translation>
    </message>
    <message>
        <source>a cycle plan&apos;s positions have no table in the lab; import the log of a delay or a ring program</source>
        <translation>循环计划的位置在实验室中没有对应表格；请导入延迟或环规程序的日志</translation>
    </message>
    <message>
        <source>the program printed PROBECYCLE NO TRIGGER: a probe did not trigger and the control stopped with alarm 101; nothing imported</source>
        <translation>程序输出了 PROBECYCLE NO TRIGGER：测头未触发，系统以报警 101 停止；未导入任何内容</translation>
    </message>
    <message>
        <source>a touch before the line PROBECYCLE PLAN that the program prints first: capture its output from the start; nothing imported</source>
        <translation>在程序首先输出的 PROBECYCLE PLAN 行之前出现了触测：请从头开始捕获其输出；未导入任何内容</translation>
    </message>
    <message>
        <source>no line PROBECYCLE PLAN: is this the DPRNT output of a ProbeCycle program? Nothing imported</source>
        <translation>没有 PROBECYCLE PLAN 行：这是 ProbeCycle 程序的 DPRNT 输出吗？未导入任何内容</translation>
    </message>
    <message>
        <source>the probe touched something during a protected move (%1): its path is obstructed, and grbl, which cannot stop a program on it, went on; check the machine; nothing imported</source>
        <translation>测头在保护移动中触碰到物体（%1）：路径受阻，而 grbl 无法因此停止程序，仍继续执行；请检查机床；未导入任何内容</translation>
    </message>
    <message>
        <source>the program printed PROBECYCLE OBSTRUCTED: the probe touched something during a protected move and the control stopped with alarm 102; nothing imported</source>
        <translation>程序输出了 PROBECYCLE OBSTRUCTED：测头在保护移动中触碰到物体，系统以报警 102 停止；未导入任何内容</translation>
    </message>
    <message>
        <source>the program&apos;s result line gives %1 %2, its touches give %3: was the program edited, or written from another plan? Nothing imported</source>
        <translation>程序的结果行给出 %1 %2，其触测给出 %3：程序是否被修改过，或由另一个计划生成？未导入任何内容</translation>
    </message>
    <message>
        <source>a %1 plan has no feature result: its import is the lab&apos;s CSV</source>
        <translation>%1 计划没有特征结果：其导入结果是实验室的 CSV</translation>
    </message>
    <message>
        <source>the cycle plan has no readable value %1: write the program and its plan again with this version of ProbeCycle</source>
        <translation>循环计划中没有可读取的值 %1：请用此版本的 ProbeCycle 重新生成程序及其计划</translation>
    </message>
    <message>
        <source>the cycle plan&apos;s recorded touches do not make the sides of its %1: was the plan file edited?</source>
        <translation>循环计划中记录的触测不能构成其%1的各侧：计划文件是否被修改过？</translation>
    </message>
    <message>
        <source>this line is from a %1 log, and no line is from a %2 log: import it as %1 (--dialect %1); nothing imported</source>
        <translation>此行来自 %1 日志，且没有任何行来自 %2 日志：请按 %1 导入（--dialect %1）；未导入任何内容</translation>
    </message>
    <message>
        <source>the console does not open with the plan&apos;s signature (four [PRB:...:0] answers to the protected moves before the first probe): it is from another plan&apos;s or an older ProbeCycle&apos;s program (make the program again from this plan), or the probe touched something during those moves (give it free air); nothing imported</source>
        <translation>控制台输出不以计划签名开头（第一次探测之前对保护移动的四个 [PRB:...:0] 应答）：它来自另一个计划或旧版 ProbeCycle 的程序（请按此计划重新生成程序），或者测头在这些移动中碰到了东西（请留出空间）；未导入任何内容</translation>
    </message>
    <message>
        <source>the console is from another plan (its signature reads %1, this plan&apos;s is %2): give the plan the program was made from; nothing imported</source>
        <translation>控制台输出来自另一个计划（其签名为 %1，本计划为 %2）：请提供生成该程序所用的计划；未导入任何内容</translation>
    </message>
    <message>
        <source>#%1 is listed again with another value (first on line %2): the list holds more than one output; nothing imported</source>
        <translation>#%1 再次出现且值不同（首次在第 %2 行）：列表包含多次输出；未导入任何内容</translation>
    </message>
    <message>
        <source>no value of #%1 in the list: list every common variable from #500 to #%2 that the program set; nothing imported</source>
        <translation>列表中没有 #%1 的值：请列出程序设置的 #500 至 #%2 的全部公共变量；未导入任何内容</translation>
    </message>
    <message>
        <source>no values of #500 to #503, where the program keeps its plan: is this the list of common variables after a ProbeCycle program? Nothing imported</source>
        <translation>没有 #500 至 #503 的值（程序在其中保存计划）：这是 ProbeCycle 程序运行后的公共变量列表吗？未导入任何内容</translation>
    </message>
    <message>
        <source>#504 is 101: a probe did not trigger and the program stopped at PROBE DID NOT TRIGGER; nothing imported</source>
        <translation>#504 为 101：测头未触发，程序停在 PROBE DID NOT TRIGGER；未导入任何内容</translation>
    </message>
    <message>
        <source>#504 is 102: the probe touched something during a protected move and the program stopped at PROBE PATH OBSTRUCTED; nothing imported</source>
        <translation>#504 为 102：测头在受保护移动中碰到了物体，程序停在 PROBE PATH OBSTRUCTED；未导入任何内容</translation>
    </message>
    <message>
        <source>#504 is %1: the program did not end (1 when it ends, 103 when it stops out of tolerance); nothing imported</source>
        <translation>#504 为 %1：程序未结束（结束时为 1，超差停止时为 103）；未导入任何内容</translation>
    </message>
</context>
<context>
    <name>Optimise</name>
    <message>
        <source>no setting meets the requirements: the probe&apos;s maximum feed %1 is under the lowest feed, %2</source>
        <translation>没有满足要求的设置：测头最大进给率 %1 低于最低进给率 %2</translation>
    </message>
    <message>
        <source>no setting meets the requirements: the overtravel must stay at or under %1 of the probe&apos;s limit %2 (probe.overtravel_limit_mm), and even at %3 it is %4</source>
        <translation>没有满足要求的设置：过行程须不超过测头极限 %2 (probe.overtravel_limit_mm) 的 %1，而即使在 %3 时也为 %4</translation>
    </message>
    <message>
        <source>no setting meets the requirements: a start distance of the part position uncertainty %1 plus the room to reach even %2 (%3) does not fit a %4 of %5</source>
        <translation>没有满足要求的设置：由零件位置不确定度 %1 加上即使达到 %2 所需距离 (%3) 构成的起始距离放不进尺寸为 %5 的%4</translation>
    </message>
    <message>
        <source>no setting meets every requirement</source>
        <translation>没有满足全部要求的设置</translation>
    </message>
    <message>
        <source>the overtravel fraction %1 is out of range: allowed from %2 to %3</source>
        <translation>过行程比例 %1 超出范围：允许 %2 到 %3</translation>
    </message>
    <message>
        <source>the skip input&apos;s scan period %1 limits the measuring feed; a latched input would save %2 a cycle</source>
        <translation>跳步输入的扫描周期 %1 限制了测量进给率；锁存输入每个循环可节省 %2</translation>
    </message>
    <message>
        <source>the probe&apos;s maximum feed %1 limits the cycle; a probe rated for faster feeds would save %2 a cycle</source>
        <translation>测头最大进给率 %1 限制了循环；额定进给率更高的测头每个循环可节省 %2</translation>
    </message>
    <message>
        <source>no setting meets the target uncertainty %1 (cycle.target_uncertainty_mm): the smallest achievable is %2, at %3 and cycle.repeats %4 (the probe&apos;s repeatability is %5; the budget&apos;s terms no feed changes, lobing, calibration artefact, machine repeatability and thermal drift, are %6 together)</source>
        <translation>没有设置能达到目标不确定度 %1 (cycle.target_uncertainty_mm)：可达到的最小值为 %2，在 %3 且 cycle.repeats 为 %4 时（测头重复性为 %5；预算中与进给率无关的各项——各向异性、校准标准器、机床重复性和热漂移——合计为 %6）</translation>
    </message>
    <message>
        <source>no setting meets the current uncertainty %1: the smallest achievable is %2, at %3 and cycle.repeats %4 (the probe&apos;s repeatability is %5; the budget&apos;s terms no feed changes, lobing, calibration artefact, machine repeatability and thermal drift, are %6 together)</source>
        <translation>没有设置能达到当前不确定度 %1：可达到的最小值为 %2，在 %3 且 cycle.repeats 为 %4 时（测头重复性为 %5；预算中与进给率无关的各项——各向异性、校准标准器、机床重复性和热漂移——合计为 %6）</translation>
    </message>
</context>
<context>
    <name>Parameter</name>
    <message>
        <source>Time constant</source>
        <translation>时间常数</translation>
    </message>
    <message>
        <source>Acceleration time constant T: the control reaches any programmed feed in T (a = v/T). Sets the distance to reach the feed (v*T/2) and the braking distance after the trigger, and so overtravel and cycle time. Used by the time-constant model.</source>
        <translation>加速时间常数 T：数控系统在 T 时间内达到任何编程进给率 (a = v/T)。它决定达到进给率所需的距离 (v*T/2) 和触发后的制动距离，从而影响过行程和循环时间。用于时间常数模型。</translation>
    </message>
    <message>
        <source>ms</source>
        <translation>ms</translation>
    </message>
    <message>
        <source>Max. acceleration</source>
        <translation>最大加速度</translation>
    </message>
    <message>
        <source>Maximum axis acceleration, used by the constant-acceleration and jerk-limited models for every move and for braking after the trigger.</source>
        <translation>轴的最大加速度，恒加速度模型和限加加速度模型用于每次移动及触发后的制动。</translation>
    </message>
    <message>
        <source>mm/s²</source>
        <translation>mm/s²</translation>
    </message>
    <message>
        <source>Max. jerk</source>
        <translation>最大加加速度</translation>
    </message>
    <message>
        <source>Maximum axis jerk, used by the jerk-limited (S-curve) model: lower jerk lengthens every acceleration and the braking after the trigger.</source>
        <translation>轴的最大加加速度，用于限加加速度（S 曲线）模型：加加速度越小，每次加速和触发后的制动越长。</translation>
    </message>
    <message>
        <source>mm/s³</source>
        <translation>mm/s³</translation>
    </message>
    <message>
        <source>Rapid feed</source>
        <translation>快移速度</translation>
    </message>
    <message>
        <source>mm/min</source>
        <translation>mm/min</translation>
    </message>
    <message>
        <source>Scan period</source>
        <translation>扫描周期</translation>
    </message>
    <message>
        <source>Machine response time</source>
        <translation>机床响应时间</translation>
    </message>
    <message>
        <source>Fixed latency of the control after it has seen the input. Removed by calibration, but the axis keeps moving: adds trigger speed × latency to the overtravel.</source>
        <translation>数控系统识别输入后的固定延迟。标定可消除其对测量值的影响，但轴仍在移动：过行程增加 触发速度 × 延迟。</translation>
    </message>
    <message>
        <source>Pretravel</source>
        <translation>预行程</translation>
    </message>
    <message>
        <source>Mechanical pretravel from first contact to the trigger threshold (typically 1-50 µm). Independent of speed and removed by calibration; adds to the overtravel and takes pretravel / speed.</source>
        <translation>从首次接触到触发阈值的机械预行程（通常 1-50 µm）。与速度无关，可由标定消除；它计入过行程，耗时为 预行程 / 速度。</translation>
    </message>
    <message>
        <source>µm</source>
        <translation>µm</translation>
    </message>
    <message>
        <source>Interface response time</source>
        <translation>接口响应时间</translation>
    </message>
    <message>
        <source>Time the probe interface (receiver) needs to pass the trigger to the control. Constant, so calibration removes it from the measured value, but it adds trigger speed × delay to the overtravel.</source>
        <translation>测头接口（接收器）将触发信号传给数控系统所需的时间。它是常数，因此标定可将其从测量值中消除，但过行程会增加 触发速度 × 延迟。</translation>
    </message>
    <message>
        <source>Repeatability (2σ)</source>
        <translation>重复性 (2σ)</translation>
    </message>
    <message>
        <source>Overtravel limit</source>
        <translation>过行程极限</translation>
    </message>
    <message>
        <source>Stylus deflection range of the probe in the probing direction. The axis must stop within it or the probe or stylus is damaged; short styli along Z and small bores are the critical cases.</source>
        <translation>测头在测量方向上的测针偏摆范围。轴必须在此范围内停止，否则会损坏测头或测针；沿 Z 方向的短测针和小孔是最危险的情况。</translation>
    </message>
    <message>
        <source>mm</source>
        <translation>mm</translation>
    </message>
    <message>
        <source>Reseat distance</source>
        <translation>复位距离</translation>
    </message>
    <message>
        <source>Distance the probe needs to reseat after a trigger. The two-touch backoff must clear the first touch&apos;s overtravel plus this.</source>
        <translation>触发后测头复位所需的距离。两次触测的回退距离必须大于第一次触测的过行程加上该距离。</translation>
    </message>
    <message>
        <source>Calibration feed</source>
        <translation>标定进给率</translation>
    </message>
    <message>
        <source>Feed at which the probe was calibrated. Measuring at another feed shifts the delay travel and so the measured value; 0 means calibrated at the measuring feed.</source>
        <translation>测头标定时的进给率。以其他进给率测量会改变延迟行程，从而改变测量值；0 表示在测量进给率下标定。</translation>
    </message>
    <message>
        <source>measuring feed</source>
        <translation>测量进给率</translation>
    </message>
    <message>
        <source>Feature size</source>
        <translation>特征尺寸</translation>
    </message>
    <message>
        <source>Approach distance</source>
        <translation>接近距离</translation>
    </message>
    <message>
        <source>Start distance in front of the nominal surface. Must cover the part&apos;s position uncertainty, and should cover the distance needed to reach the feed so the touch happens at full speed. Approached at the probing feed, returned at the return feed.</source>
        <translation>起始点到名义表面的距离。必须覆盖工件位置的不确定性，并应覆盖达到进给率所需的距离，使触测以全速发生。以探测进给率接近，以返回进给率返回。</translation>
    </message>
    <message>
        <source>Probing feedrate</source>
        <translation>探测进给率</translation>
    </message>
    <message>
        <source>Feed of the (first) touch; single-touch measures at it. A higher feed shortens the approach but lengthens the braking, the overtravel and the return, and raises the single-touch uncertainty.</source>
        <translation>（第一次）触测的进给率；单次触测在此进给率下测量。进给率越高，接近越短，但制动、过行程和返回越长，单次触测的不确定度也越大。</translation>
    </message>
    <message>
        <source>Measuring feedrate</source>
        <translation>测量进给率</translation>
    </message>
    <message>
        <source>Backoff</source>
        <translation>回退距离</translation>
    </message>
    <message>
        <source>Return feedrate</source>
        <translation>返回进给率</translation>
    </message>
    <message>
        <source>Feed of the backoff and of the return to the start position (start distance plus overtravel).</source>
        <translation>回退以及返回起始点（起始距离加过行程）的进给率。</translation>
    </message>
    <message>
        <source>Target uncertainty</source>
        <translation>目标不确定度</translation>
    </message>
    <message>
        <source>none</source>
        <translation>无</translation>
    </message>
    <message>
        <source>Single-touch</source>
        <translation>单次触测</translation>
    </message>
    <message>
        <source>Two-touch</source>
        <translation>两次触测</translation>
    </message>
    <message>
        <source>Surface (1 touch)</source>
        <translation>平面（1 次触测）</translation>
    </message>
    <message>
        <source>Web (2 touches)</source>
        <translation>凸台（2 次触测）</translation>
    </message>
    <message>
        <source>Pocket (2 touches)</source>
        <translation>槽（2 次触测）</translation>
    </message>
    <message>
        <source>Bore (4 touches)</source>
        <translation>孔（4 次触测）</translation>
    </message>
    <message>
        <source>Boss (4 touches)</source>
        <translation>圆柱（4 次触测）</translation>
    </message>
    <message>
        <source>Machine</source>
        <translation>机床</translation>
    </message>
    <message>
        <source>Probe</source>
        <translation>测头</translation>
    </message>
    <message>
        <source>Cycle</source>
        <translation>循环</translation>
    </message>
    <message>
        <source>s</source>
        <translation>s</translation>
    </message>
    <message>
        <source>Constant accel.</source>
        <translation>恒加速度</translation>
    </message>
    <message>
        <source>S-curve (jerk)</source>
        <translation>S 曲线（加加速度）</translation>
    </message>
    <message>
        <source>µs</source>
        <translation>µs</translation>
    </message>
    <message>
        <source>Time constant (T)</source>
        <translation>时间常数 (T)</translation>
    </message>
    <message>
        <source>Acceleration model</source>
        <translation>加速模型</translation>
    </message>
    <message>
        <source>The control latches (or timestamps) the position in hardware at the trigger: the scan-period wait leaves the measured value, but not the travel - the machine still stops late.</source>
        <translation>数控系统在触发时由硬件锁存（或打时间戳）位置：扫描周期等待不再影响测量值，但不影响行程——机床仍然会晚停。</translation>
    </message>
    <message>
        <source>Latched (hardware-captured) input</source>
        <translation>锁存（硬件捕获）输入</translation>
    </message>
    <message>
        <source>Single-touch measures at the probing feed. Two-touch finds the surface fast, backs off, and measures with a slow second touch.</source>
        <translation>单次触测以探测进给率测量。两次触测先快速找到表面，回退，再以慢速的第二次触测进行测量。</translation>
    </message>
    <message>
        <source>Strategy</source>
        <translation>策略</translation>
    </message>
    <message>
        <source>Feature</source>
        <translation>特征</translation>
    </message>
    <message>
        <source>The knee is the lowest probing feed whose cycle time is within this fraction of the fastest cycle, among the feeds whose overtravel stays within the probe&apos;s limit. Faster than the knee buys little time for more overtravel and uncertainty.</source>
        <translation>拐点是循环时间与最快循环相差不超过此比例的最低探测进给率，只在过行程不超过测头极限的进给率中查找。高于拐点的进给率节省的时间很少，却增大过行程和不确定度。</translation>
    </message>
    <message>
        <source>Knee tolerance</source>
        <translation>拐点容差</translation>
    </message>
    <message>
        <source>%</source>
        <translation>%</translation>
    </message>
    <message>
        <source>Two-touch: distance the probe backs off after the first touch, from where it stopped or from the recorded trigger position (Backoff from). It must leave the second touch room to reseat the probe and to reach the measuring feed; any more is approached again at the slow measuring feed and wasted.</source>
        <translation>两次触测：第一次触测后测头的回退距离，从停止处或从记录的触发位置算起（“回退起点”）。它必须给第二次触测留出测头复位和加速到测量进给率的距离；多出的部分要以慢速测量进给率重新接近，白白浪费时间。</translation>
    </message>
    <message>
        <source>Two-touch: where the backoff is measured from. stop: from where the probe stopped after the first touch (Renishaw&apos;s cycles). trigger: from the trigger position the control recorded (the skip position a macro reads); the axis then moves back its overtravel beyond that position as well.</source>
        <translation>两次触测：回退距离的起点。stop：从第一次触测后测头停止处算起（雷尼绍循环）。trigger：从数控系统记录的触发位置算起（宏程序读取的跳转位置）；此时轴还要额外退回越过该位置的过行程。</translation>
    </message>
    <message>
        <source>Backoff from</source>
        <translation>回退起点</translation>
    </message>
    <message>
        <source>Where it stopped</source>
        <translation>停止处</translation>
    </message>
    <message>
        <source>Trigger position</source>
        <translation>触发位置</translation>
    </message>
    <message>
        <source>Rapid feed: a boss or web lifts over its wall at it, away from the part. Moves toward the part are protected, at the positioning feed.</source>
        <translation>快移速度：测量圆柱或凸台时以此速度抬起越过侧壁（远离工件）。朝向工件的移动为保护移动，使用定位进给率。</translation>
    </message>
    <message>
        <source>Positioning feed</source>
        <translation>定位进给率</translation>
    </message>
    <message>
        <source>Boss or web: height the probe lifts above the measuring depth to pass over the wall between touches (up at the rapid feed, down at the positioning feed).</source>
        <translation>圆柱或凸台：各次触测之间测头抬到测量深度以上越过侧壁的高度（以快移速度抬起，以定位进给率下降）。</translation>
    </message>
    <message>
        <source>Clearance height</source>
        <translation>安全高度</translation>
    </message>
    <message>
        <source>How the control accelerates before interpolation: a time constant (a = v/T, common on many controls), a constant acceleration, a jerk-limited S-curve, or none (the feed is commanded at once and stopped at once, as on a skip block without acc/dec; then the filter after interpolation and the servo shape the motion). Sets every move time and the braking distance after the trigger.</source>
        <translation>控制系统在插补前如何加速：时间常数（a = v/T，多数系统常用）、恒定加速度、限制加加速度的S曲线，或无（进给立即给出、立即停止，如无加减速的跳跃程序段；此时由插补后滤波器和伺服决定运动）。决定每段移动的时间和触发后的制动距离。</translation>
    </message>
    <message>
        <source>Acc/dec filter after interpolation: none, linear (a moving average of the commanded speed over the filter time), exponential (first order, time constant = the filter time) or bell (two moving averages, the filter time and the second filter time). After the trigger the axis drains it: v*T/2 more (linear), v*T (exponential), v*(T1+T2)/2 (bell).</source>
        <translation>插补后加减速滤波器：无、直线型（指令速度在滤波时间内的移动平均）、指数型（一阶，时间常数 = 滤波时间）或铃型（两个移动平均：滤波时间和第二滤波时间）。触发后轴还要走完滤波器的滞后：直线型再走 v*T/2，指数型 v*T，铃型 v*(T1+T2)/2。</translation>
    </message>
    <message>
        <source>Filter after interpolation</source>
        <translation>插补后滤波器</translation>
    </message>
    <message>
        <source>Time of the filter after interpolation: the linear filter&apos;s window, the exponential filter&apos;s time constant, or the bell filter&apos;s first window (Fanuc: the cutting-feed acc/dec time constant).</source>
        <translation>插补后滤波器的时间：直线型的窗口、指数型的时间常数或铃型的第一窗口（Fanuc：切削进给加减速时间常数）。</translation>
    </message>
    <message>
        <source>Filter time</source>
        <translation>滤波时间</translation>
    </message>
    <message>
        <source>Second window of the bell filter after interpolation (the S-shaping time).</source>
        <translation>插补后铃型滤波器的第二窗口（S形平滑时间）。</translation>
    </message>
    <message>
        <source>Second filter time</source>
        <translation>第二滤波时间</translation>
    </message>
    <message>
        <source>Servo time constant Tp = 1/Kv (position loop gain): the axis trails the command by v*Tp and, after the command stops, travels that much more. 0 = the axis follows the command exactly.</source>
        <translation>伺服时间常数 Tp = 1/Kv（位置环增益）：轴滞后指令 v*Tp，指令停止后还要再走这么多。0 = 轴完全跟随指令。</translation>
    </message>
    <message>
        <source>Servo time constant</source>
        <translation>伺服时间常数</translation>
    </message>
    <message>
        <source>In-position width: with a filter or a servo lag, a move counts as done when the axis is within this of its commanded end, and the next move starts then. The overtravel is still where the axis comes to rest.</source>
        <translation>到位宽度（到位检测）：有滤波器或伺服滞后时，轴距指令终点小于此值即认为移动完成，随即开始下一段移动。过行程仍按轴最终停止的位置计算。</translation>
    </message>
    <message>
        <source>In-position width</source>
        <translation>到位宽度</translation>
    </message>
    <message>
        <source>ideal servo</source>
        <translation>理想伺服</translation>
    </message>
    <message>
        <source>None (feed at once)</source>
        <translation>无（立即给出进给）</translation>
    </message>
    <message>
        <source>None</source>
        <translation>无</translation>
    </message>
    <message>
        <source>Linear (moving average)</source>
        <translation>直线型（移动平均）</translation>
    </message>
    <message>
        <source>Exponential</source>
        <translation>指数型</translation>
    </message>
    <message>
        <source>Bell (two averages)</source>
        <translation>铃型（两次平均）</translation>
    </message>
    <message>
        <source>The probe maker&apos;s rated maximum probing speed. A touch faster than it is an error: the probe may not trigger reliably or may be damaged. 0 means no limit.</source>
        <translation>测头厂商给定的最大探测速度。触测快于此值即为错误：测头可能无法可靠触发或损坏。0 表示无限制。</translation>
    </message>
    <message>
        <source>Probe&apos;s maximum feed</source>
        <translation>测头最大进给率</translation>
    </message>
    <message>
        <source>Part position uncertainty</source>
        <translation>零件位置不确定度</translation>
    </message>
    <message>
        <source>How many times the measuring touch is made and averaged (two-touch: back off and touch again at the measuring feed; single-touch: back to the start and touch again). The random parts of the uncertainty, scan phase and repeatability, fall by the square root of this; each repeat adds its moves to the cycle. A whole number.</source>
        <translation>测量触测的次数，结果取平均（两次触测：回退后以测量进给率再次触测；单次触测：回到起点再次触测）。不确定度的随机部分（扫描相位和重复性）按此数的平方根减小；每次重复都会在循环中增加相应的移动。须为整数。</translation>
    </message>
    <message>
        <source>Measurements</source>
        <translation>测量次数</translation>
    </message>
    <message>
        <source>Parts made per year, for the savings: time saved per part times this. 0 means savings are not shown.</source>
        <translation>每年生产的零件数，用于计算节省：每件节省的时间乘以此数。0 表示不显示节省。</translation>
    </message>
    <message>
        <source>Parts per year</source>
        <translation>年产零件数</translation>
    </message>
    <message>
        <source>How many times this probing cycle runs per part, for the savings. 0 means savings are not shown.</source>
        <translation>每个零件运行此测量循环的次数，用于计算节省。0 表示不显示节省。</translation>
    </message>
    <message>
        <source>Cycles per part</source>
        <translation>每件循环数</translation>
    </message>
    <message>
        <source>What an hour of the machine costs, in any currency, for the savings per year. 0 means the savings are shown in hours only.</source>
        <translation>机床每小时的费用（任意货币），用于计算每年的节省。0 表示只以小时显示节省。</translation>
    </message>
    <message>
        <source>Machine rate per hour</source>
        <translation>机床小时费率</translation>
    </message>
    <message>
        <source>no limit</source>
        <translation>无限制</translation>
    </message>
    <message>
        <source>known part</source>
        <translation>位置已知</translation>
    </message>
    <message>
        <source>×</source>
        <translation>×</translation>
    </message>
    <message>
        <source>/year</source>
        <translation>/年</translation>
    </message>
    <message>
        <source>not shown</source>
        <translation>不显示</translation>
    </message>
    <message>
        <source>/part</source>
        <translation>/件</translation>
    </message>
    <message>
        <source>/h</source>
        <translation>/小时</translation>
    </message>
    <message>
        <source>hours only</source>
        <translation>仅小时</translation>
    </message>
    <message>
        <source>How far each probing move searches past the farthest place its surface can be (the nominal surface plus the part position uncertainty; for a second touch or a repeat, where the touch before stopped) before the control gives up. It must reach past the touch&apos;s stop: a search that ends sooner is braking when it touches, triggers below the feed and stops at its end. 0 means automatic: halfway from the touch&apos;s stop to the probe&apos;s overtravel limit.</source>
        <translation>每次探测移动在其表面可能所在的最远位置（名义表面加上零件位置不确定度；对第二次触测或重复触测，为前一次触测的停止位置）之后继续搜索的距离，超过后数控系统放弃。它必须超过该次触测的停止位置：更早结束的搜索在触碰时已在减速，触发速度低于进给率并停在搜索终点。0 表示自动：取该次触测停止位置与测头过行程极限的中点。</translation>
    </message>
    <message>
        <source>Search beyond surface</source>
        <translation>超出表面的搜索距离</translation>
    </message>
    <message>
        <source>automatic</source>
        <translation>自动</translation>
    </message>
    <message>
        <source>Time the control adds at each block change, after a move ends and before the next starts: block processing, the wait for the in-position check and, after a probing move, for the skip position to be read. Every move of the cycle (touches, backoffs, returns, positioning moves) adds it once. 0 means none.</source>
        <translation>数控系统在每次程序段切换时增加的时间，即一个移动结束后、下一个开始之前：程序段处理、等待到位检测，以及探测移动之后等待读取跳跃位置。循环中的每个移动（触测、回退、返回、定位移动）各增加一次。0 表示无。</translation>
    </message>
    <message>
        <source>Block change time</source>
        <translation>程序段切换时间</translation>
    </message>
    <message>
        <source>Period at which the control scans the skip input (about 4 ms on a standard input, 4 µs on a high-speed input). The wait for the next scan, from nothing to a full period, is the single-touch uncertainty (trigger speed × scan period); the overtravel takes the worst case, a full period of travel, and the cycle time the mean wait, half a period.</source>
        <translation>数控系统扫描跳跃输入的周期（标准输入约 4 ms，高速输入约 4 µs）。等待下一次扫描的时间在零到一个完整周期之间，它决定单次触测的不确定度（触发速度 × 扫描周期）；过行程按最坏情况计入一个完整周期的行程，循环时间按平均等待计入半个周期。</translation>
    </message>
    <message>
        <source>A surface needs one touch, a web or pocket two opposite touches, a bore or boss four; the probe moves out from the feature&apos;s centre to each touch and back at the positioning feed.</source>
        <translation>平面需要一次触测，凸台或槽需要两次相对的触测，孔或圆柱需要四次；测头以定位进给率从特征中心移到每次触测处并返回。</translation>
    </message>
    <message>
        <source>Distance between opposite stylus-centre contact points: web or pocket width, bore or boss diameter less the ball diameter. Sets the positioning moves out from the centre to each touch and back; unused for a surface.</source>
        <translation>相对两个测针球心接触点之间的距离：凸台或槽的宽度、孔或圆柱直径减去测球直径。它决定从中心到每次触测处并返回的定位移动；测量平面时不使用。</translation>
    </message>
    <message>
        <source>Feed of the second, measuring touch of two-touch (typically 30 mm/min). Sets the two-touch uncertainty; the second approach, the backoff less where the first touch stopped (on average), is travelled at it.</source>
        <translation>两次触测中第二次（测量）触测的进给率（通常 30 mm/min）。决定两次触测的不确定度；第二次接近（回退距离减去第一次触测的平均过行程）以此进给率完成。</translation>
    </message>
    <message>
        <source>Web, pocket, bore, boss: feed of the protected positioning moves (probe armed, so a collision stops the axis) from the feature&apos;s centre out to each touch and back to the centre.</source>
        <translation>凸台、槽、孔、圆柱：保护定位移动的进给率（测头已启用，碰撞会使轴停止），用于从特征中心移到每次触测处并返回中心。</translation>
    </message>
    <message>
        <source>The highest feed override the operator may turn the cycle up to. Feed override speeds up every move at feed, the touches and the protected positioning moves too, so every overtravel check holds at it: the stylus&apos;s limit, the searches past each stop and the backoff that must clear the first touch&apos;s stop. The cycle time is at 100 %. 120 % is as far as every common control&apos;s dial turns; set what your machine&apos;s panel allows (Fanuc-type and Heidenhain 150 %, Haas 200 %), or 100 where the program locks the override.</source>
        <translation>操作者可将循环调到的最高进给倍率。进给倍率会加快每个以进给速度执行的移动，包括各次触测和受保护的定位移动，因此所有过行程检查都按该倍率进行：测针极限、越过每个停止点的搜索，以及必须越过第一次触测停止点的回退。循环时间按 100 % 计算。120 % 是所有常见数控系统的倍率旋钮都能达到的值；请设为您机床面板允许的值（Fanuc 类和 Heidenhain 为 150 %，Haas 为 200 %），若程序锁定倍率则设为 100。</translation>
    </message>
    <message>
        <source>Highest feed override</source>
        <translation>最高进给倍率</translation>
    </message>
    <message>
        <source>Web, pocket, bore, boss: the cycle program checks the measured size (width or diameter) against the feature size plus or minus this, and the import does the same. 0 means no check.</source>
        <translation>凸台、槽、孔、圆柱：循环程序将测得的尺寸（宽度或直径）与特征尺寸加减此值进行比较，导入时也同样检查。0 表示不检查。</translation>
    </message>
    <message>
        <source>Size tolerance</source>
        <translation>尺寸公差</translation>
    </message>
    <message>
        <source>What the cycle program does when the measured size is outside its tolerance. flag: sets its out-of-tolerance variable and writes OUT OF TOLERANCE to its log, then goes on. stop: the same, then stops with an alarm.</source>
        <translation>测得尺寸超出公差时循环程序的处理方式。flag：置位超差变量并在日志中写入 OUT OF TOLERANCE，然后继续运行。stop：同上，然后以报警停止。</translation>
    </message>
    <message>
        <source>Flag it and go on</source>
        <translation>标记并继续</translation>
    </message>
    <message>
        <source>Stop with an alarm</source>
        <translation>报警停止</translation>
    </message>
    <message>
        <source>If out of tolerance</source>
        <translation>超差时</translation>
    </message>
    <message>
        <source>Unidirectional positioning repeatability of the axes, 2 sigma, from the machine&apos;s acceptance test (ISO 230-2 states R = 4 sigma: enter R/2). A term of the uncertainty budget: u = value/2, the same for repeated touches.</source>
        <translation>各轴的单向定位重复性，2 sigma，取自机床验收检测（ISO 230-2 给出的 R = 4 sigma：请输入 R/2）。不确定度预算的一项：u = 数值/2，重复触测时相同。</translation>
    </message>
    <message>
        <source>Positioning repeatability (2σ)</source>
        <translation>定位重复性 (2σ)</translation>
    </message>
    <message>
        <source>How far the machine&apos;s and the part&apos;s temperature may move the measured point between calibration and measurement, ± (measure it: probe an artefact again after the time a batch takes). A term of the uncertainty budget: u = value/√3, the same for repeated touches.</source>
        <translation>在校准与测量之间，机床和工件的温度可能使测量点移动的量，±（实测方法：经过一批工件的加工时间后再次测量标准器）。不确定度预算的一项：u = 数值/√3，重复触测时相同。</translation>
    </message>
    <message>
        <source>Thermal drift (±)</source>
        <translation>热漂移 (±)</translation>
    </message>
    <message>
        <source>Unidirectional repeatability of the probe, 2 sigma. A term of the uncertainty budget with the scan-period range: u = value/2, averaged over repeated touches.</source>
        <translation>测头的单向重复性，2 sigma。与扫描周期范围一起构成不确定度预算的一项：u = 数值/2，按重复触测取平均。</translation>
    </message>
    <message>
        <source>Pretravel variation over the directions the cycle probes that calibration leaves, ± (the data sheet&apos;s 2D lobing: about 1 µm for a kinematic probe, 0.25 µm for a strain-gauge one; 0 when the probe is calibrated in every direction it measures). A term of the uncertainty budget: u = value/√3, the same for repeated touches.</source>
        <translation>校准后在循环测量的各方向上残留的预行程变化，±（数据表中的二维各向异性：机械式测头约 1 µm，应变片式测头约 0.25 µm；测头在每个测量方向上都已校准时为 0）。不确定度预算的一项：u = 数值/√3，重复触测时相同。</translation>
    </message>
    <message>
        <source>Lobing (±)</source>
        <translation>各向异性 (±)</translation>
    </message>
    <message>
        <source>Expanded uncertainty (k = 2) of the artefact the probe is calibrated on, from its calibration certificate (a ring gauge&apos;s diameter, a gauge block&apos;s length). A term of the uncertainty budget: u = value/2, the same for repeated touches.</source>
        <translation>测头校准所用标准器的扩展不确定度 (k = 2)，取自其校准证书（环规的直径、量块的长度）。不确定度预算的一项：u = 数值/2，重复触测时相同。</translation>
    </message>
    <message>
        <source>Calibration artefact (k = 2)</source>
        <translation>校准标准器 (k = 2)</translation>
    </message>
    <message>
        <source>How far the surface may lie from its nominal position (a casting, a part clamped by hand). The start distance must cover it plus the distance to reach the probing feed, so the touch is at full feed wherever the part lies. 0 means a known part: its surface is where the drawing puts it.</source>
        <translation>表面可能偏离其名义位置的距离（铸件、手工装夹的零件）。起始距离必须覆盖它再加上达到探测进给率所需的距离，这样无论零件位于何处，触测都在全进给率下进行。0 表示已知零件：其表面就在图纸所定的位置。</translation>
    </message>
    <message>
        <source>Target for the expanded (k = 2) uncertainty of the measured point, the whole budget (the trigger&apos;s part and the terms no feed changes); a warning appears above it. 0 means no target.</source>
        <translation>测量点扩展不确定度 (k = 2) 的目标值，针对整个预算（触发部分以及与进给率无关的各项）；超过时给出警告。0 表示无目标。</translation>
    </message>
    <message>
        <source>The shortest start distance the optimiser proposes: no touch starts closer to its nominal surface, whatever the part position uncertainty and the feed allow. 0 means no minimum.</source>
        <translation>优化器建议的最短起始距离：无论零件位置不确定度和进给率允许多少，任何触测都不会从更靠近名义表面的位置开始。0 表示无最小值。</translation>
    </message>
    <message>
        <source>Shortest approach</source>
        <translation>最短接近距离</translation>
    </message>
    <message>
        <source>The slowest probing or measuring feed the optimiser proposes (the probe maker&apos;s or the shop&apos;s slowest probing speed); with the probe&apos;s maximum feed and the rapid feed it bounds every feed the optimiser tries.</source>
        <translation>优化器建议的最低探测或测量进给率（测头制造商或车间规定的最低探测速度）；它与测头最大进给率和快移速度一起限定优化器尝试的所有进给率。</translation>
    </message>
    <message>
        <source>Slowest feed</source>
        <translation>最低进给率</translation>
    </message>
</context>
<context>
    <name>PdfReport</name>
    <message>
        <source>Page %1 of %2</source>
        <translation>第 %1 页，共 %2 页</translation>
    </message>
</context>
<context>
    <name>Phase</name>
    <message>
        <source>Approach</source>
        <translation>接近</translation>
    </message>
    <message>
        <source>Pretravel</source>
        <translation>预行程</translation>
    </message>
    <message>
        <source>Deceleration</source>
        <translation>减速</translation>
    </message>
    <message>
        <source>Backoff</source>
        <translation>回退</translation>
    </message>
    <message>
        <source>2nd approach</source>
        <translation>第二次接近</translation>
    </message>
    <message>
        <source>2nd pretravel</source>
        <translation>第二次预行程</translation>
    </message>
    <message>
        <source>2nd deceleration</source>
        <translation>第二次减速</translation>
    </message>
    <message>
        <source>Return</source>
        <translation>返回</translation>
    </message>
    <message>
        <source>Positioning</source>
        <translation>定位</translation>
    </message>
    <message>
        <source>Interface delay</source>
        <translation>接口延迟</translation>
    </message>
    <message>
        <source>Controller delay</source>
        <translation>控制器延迟</translation>
    </message>
    <message>
        <source>2nd interface delay</source>
        <translation>第二次接口延迟</translation>
    </message>
    <message>
        <source>2nd controller delay</source>
        <translation>第二次控制器延迟</translation>
    </message>
    <message>
        <source>Lift</source>
        <translation>抬起</translation>
    </message>
    <message>
        <source>Lower</source>
        <translation>下降</translation>
    </message>
    <message>
        <source>Block changes</source>
        <translation>程序段切换</translation>
    </message>
</context>
<context>
    <name>Preset</name>
    <message>
        <source>Fanuc-type: exponential acc/dec after interpolation + servo</source>
        <translation>Fanuc 类型：插补后指数型加减速 + 伺服</translation>
    </message>
    <message>
        <source>The skip feed is commanded at once and smoothed after interpolation by an exponential filter (32 ms), then a servo lag (33 ms); 20 ms from trigger to reaction with the probe&apos;s 2 ms. Overtravel at cruise: F/60 × (20 + Tc + Ts) / 1000 mm. Typical values: replace them with your machine&apos;s.</source>
        <translation>跳跃进给立即给出，插补后经指数型滤波器（32 ms）平滑，再经伺服滞后（33 ms）；从触发到响应共 20 ms（含测头的 2 ms）。匀速时的过行程：F/60 × (20 + Tc + Ts) / 1000 mm。典型值：请换成您机床的值。</translation>
    </message>
    <message>
        <source>High-speed skip input (4 µs scan)</source>
        <translation>高速跳跃输入（4 µs 扫描）</translation>
    </message>
    <message>
        <source>A direct, high-speed skip input scanned every 4 µs with a 0.5 ms latency. Typical values: replace them with your machine&apos;s.</source>
        <translation>每 4 µs 扫描一次、延迟 0.5 ms 的直接高速跳跃输入。典型值：请替换为您机床的实测值。</translation>
    </message>
    <message>
        <source>Latched input (position captured in hardware)</source>
        <translation>锁存输入（硬件捕获位置）</translation>
    </message>
    <message>
        <source>The control latches the axis positions at the trigger: the scan wait leaves the measured value but not the travel. Typical values: replace them with your machine&apos;s.</source>
        <translation>数控系统在触发时锁存各轴位置：扫描等待不再影响测量值，但仍影响行程。典型值：请替换为您机床的实测值。</translation>
    </message>
    <message>
        <source>Linear acc/dec after interpolation</source>
        <translation>插补后直线型加减速</translation>
    </message>
    <message>
        <source>The feed is commanded at once and averaged over 64 ms after interpolation, then a 20 ms servo lag: a touch during the ramp does not brake at once. Typical values: replace them with your machine&apos;s.</source>
        <translation>进给立即给出，插补后在 64 ms 内平均，再经 20 ms 伺服滞后：加速中触碰时不会立即制动。典型值：请换成您机床的值。</translation>
    </message>
    <message>
        <source>LinuxCNC (1 ms servo period)</source>
        <translation>LinuxCNC（1 ms 伺服周期）</translation>
    </message>
    <message>
        <source>LinuxCNC 2.9 in exact stop (G61.1), as ProbeCycle&apos;s programs run it: constant acceleration (1000 mm/s²), the probe input read once per 1 ms servo period and braking two periods later, no filter after interpolation, ideal drives. Typical values: replace them with your machine&apos;s, or read them from its INI file with File &gt; Import Machine.</source>
        <translation>准停模式（G61.1）下的 LinuxCNC 2.9，与 ProbeCycle 的程序运行方式相同：恒定加速度（1000 mm/s²），测头输入每个 1 ms 伺服周期读取一次，两个周期后开始制动，无插补后滤波器，理想驱动。典型值：请换成您机床的值，或用“文件 &gt; 导入机床”从其 INI 文件读取。</translation>
    </message>
    <message>
        <source>Mitsubishi-type: G31 without acc/dec</source>
        <translation>三菱类型：无加减速的 G31</translation>
    </message>
    <message>
        <source>The skip block moves without acceleration: the command starts and stops at once and only the servo lag (Tp = 30 ms) smooths it; 5 ms response delay with the probe&apos;s 2 ms, 1 ms scan. Overtravel: F/60 × (Tp + t1 ± t2). Typical values: replace them with your machine&apos;s.</source>
        <translation>跳跃程序段不加减速：指令立即开始、立即停止，只有伺服滞后（Tp = 30 ms）使其平滑；响应延迟 5 ms（含测头的 2 ms），扫描 1 ms。过行程：F/60 × (Tp + t1 ± t2)。典型值：请换成您机床的值。</translation>
    </message>
    <message>
        <source>Standard skip input (4 ms scan)</source>
        <translation>标准跳跃输入（4 ms 扫描）</translation>
    </message>
    <message>
        <source>A skip input scanned every 4 ms with a 2 ms latency, on a time-constant machine (T = 60 ms) without a filter after interpolation or servo lag. Typical values: replace them with your machine&apos;s.</source>
        <translation>跳跃输入每 4 ms 扫描一次，延迟 2 ms，机床采用时间常数（T = 60 ms），无插补后滤波器、无伺服滞后。典型值：请换成您机床的值。</translation>
    </message>
    <message>
        <source>Kinematic probe, optical transmission</source>
        <translation>机械式测头，光学传输</translation>
    </message>
    <message>
        <source>Resistive kinematic probe with an optical receiver: 5 µm pretravel, 2 ms interface response, 1 µm repeatability. Typical values: replace them with the ones you measure.</source>
        <translation>带光学接收器的电阻式机械测头：预行程 5 µm，接口响应 2 ms，重复性 1 µm。典型值：请替换为您的实测值。</translation>
    </message>
    <message>
        <source>Kinematic probe, radio transmission</source>
        <translation>机械式测头，无线电传输</translation>
    </message>
    <message>
        <source>Kinematic probe with a radio receiver: the transmission adds about 10 ms of interface response. Typical values: replace them with the ones you measure.</source>
        <translation>带无线电接收器的机械式测头：传输使接口响应增加约 10 ms。典型值：请替换为您的实测值。</translation>
    </message>
    <message>
        <source>Short stylus / small bore (2 mm overtravel)</source>
        <translation>短测针 / 小孔（过行程 2 mm）</translation>
    </message>
    <message>
        <source>A probe with a short stylus or in a small bore, where only about 2 mm of overtravel is safe. Typical values: replace them with the ones you measure.</source>
        <translation>短测针或在小孔中测量的测头，只有约 2 mm 的过行程是安全的。典型值：请替换为您的实测值。</translation>
    </message>
    <message>
        <source>Strain-gauge probe (high accuracy)</source>
        <translation>应变片式测头（高精度）</translation>
    </message>
    <message>
        <source>Strain-gauge probe: sub-micrometre pretravel and repeatability, low trigger force. Typical values: replace them with the ones you measure.</source>
        <translation>应变片式测头：亚微米级的预行程和重复性，触发力小。典型值：请替换为您的实测值。</translation>
    </message>
</context>
<context>
    <name>Program</name>
    <message>
        <source>the backoff %1 does not clear the first touch&apos;s overtravel %2: set cycle.backoff_mm to at least %3 (the recommended backoff)</source>
        <translation>回退距离 %1 不足以覆盖第一次触测的过行程 %2：请将 cycle.backoff_mm 设为至少 %3（推荐回退距离）</translation>
    </message>
    <message>
        <source>the gauge (%1) leaves the ball (%2) no more room than the centre tolerance %3: a larger gauge or a smaller ball</source>
        <translation>环规（%1）给测球（%2）留出的空间不大于中心公差 %3：需要更大的环规或更小的测球</translation>
    </message>
    <message>
        <source>the plan turns the spindle to %1 deg; a %2 program turns it to 180 deg only, with the command given as --orient-180</source>
        <translation>计划将主轴转到 %1°；%2 程序只能用 --orient-180 给出的指令将其转到 180°</translation>
    </message>
    <message>
        <source>%1: the ring program turns the spindle to 180 deg, and %2 controls have no common word for that (M19 with an angle differs by maker and machine): give your control&apos;s command, e.g. &quot;M19 R180.&quot; if your manual says so; ProbeCycle does not guess it</source>
        <translation>%1：环规程序需将主轴转到 180°，而 %2 系统没有通用的指令（带角度的 M19 因厂商和机床而异）：请给出您的系统的指令，例如手册如此规定时用 &quot;M19 R180.&quot;；ProbeCycle 不会猜测</translation>
    </message>
    <message>
        <source>%1: got &apos;%2&apos;; allowed: one block of at most 60 upper-case letters, digits, spaces and . + - # [ ] =</source>
        <translation>%1：得到“%2”；允许：一个程序段，最多 60 个大写字母、数字、空格及 . + - # [ ] =</translation>
    </message>
    <message>
        <source>at %1 and up to %4 % feed override the model&apos;s overtravel is %2, at or over the probe&apos;s limit %3: lower the feed (or cycle.feed_override_max_pct) or check the scenario</source>
        <translation>在 %1 及最高 %4 % 进给倍率下，模型的过行程为 %2，达到或超过测头极限 %3：请降低进给（或 cycle.feed_override_max_pct）或检查场景</translation>
    </message>
    <message>
        <source>the plan records %1 touches; a %2 program keeps at most %3 (three common variables each, #%4 to #%5): use fewer feeds or repeats</source>
        <translation>该计划记录 %1 次触碰；%2 程序最多保存 %3 次（每次三个公共变量，#%4 至 #%5）：请减少进给或重复次数</translation>
    </message>
    <message>
        <source>%1: got %2; allowed: 1 or 2 (the probe&apos;s input), negative for a probe whose signal falls when it triggers: 1, -1, 2, -2</source>
        <translation>%1：得到 %2；允许：1 或 2（测头输入），触发时信号下降的测头取负值：1、-1、2、-2</translation>
    </message>
</context>
<context>
    <name>ReportWord</name>
    <message>
        <source>Ring gauge</source>
        <translation>环规</translation>
    </message>
    <message>
        <source>Circle fits by spindle orientation</source>
        <translation>按主轴方位拟合的圆</translation>
    </message>
    <message>
        <source>Points</source>
        <translation>各点</translation>
    </message>
    <message>
        <source>Length</source>
        <translation>长度</translation>
    </message>
    <message>
        <source>Fit</source>
        <translation>拟合</translation>
    </message>
    <message>
        <source>Groups</source>
        <translation>分组</translation>
    </message>
    <message>
        <source>Feeds</source>
        <translation>各进给率</translation>
    </message>
    <message>
        <source>Touches</source>
        <translation>触测</translation>
    </message>
    <message>
        <source>C axis</source>
        <translation>C 轴</translation>
    </message>
    <message>
        <source>Summary</source>
        <translation>汇总</translation>
    </message>
    <message>
        <source>Quantity</source>
        <translation>量</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>数值</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>单位</translation>
    </message>
    <message>
        <source>Uncertainty</source>
        <translation>不确定度</translation>
    </message>
    <message>
        <source>Count</source>
        <translation>数量</translation>
    </message>
    <message>
        <source>Min</source>
        <translation>最小</translation>
    </message>
    <message>
        <source>Max</source>
        <translation>最大</translation>
    </message>
    <message>
        <source>Mean</source>
        <translation>平均</translation>
    </message>
    <message>
        <source>RMS</source>
        <translation>均方根</translation>
    </message>
    <message>
        <source>Std. deviation</source>
        <translation>标准差</translation>
    </message>
    <message>
        <source>Gauge diameter</source>
        <translation>环规直径</translation>
    </message>
    <message>
        <source>Centre X</source>
        <translation>中心 X</translation>
    </message>
    <message>
        <source>Centre Y</source>
        <translation>中心 Y</translation>
    </message>
    <message>
        <source>Runout X</source>
        <translation>跳动 X</translation>
    </message>
    <message>
        <source>Runout Y</source>
        <translation>跳动 Y</translation>
    </message>
    <message>
        <source>Runout</source>
        <translation>跳动</translation>
    </message>
    <message>
        <source>Effective radius</source>
        <translation>有效半径</translation>
    </message>
    <message>
        <source>Radius X+</source>
        <translation>半径 X+</translation>
    </message>
    <message>
        <source>Radius X-</source>
        <translation>半径 X-</translation>
    </message>
    <message>
        <source>Radius Y+</source>
        <translation>半径 Y+</translation>
    </message>
    <message>
        <source>Radius Y-</source>
        <translation>半径 Y-</translation>
    </message>
    <message>
        <source>Largest residual</source>
        <translation>最大残差</translation>
    </message>
    <message>
        <source>Runout limit</source>
        <translation>跳动极限</translation>
    </message>
    <message>
        <source>Residual limit</source>
        <translation>残差极限</translation>
    </message>
    <message>
        <source>Spindle orientation</source>
        <translation>主轴方位</translation>
    </message>
    <message>
        <source>Radius</source>
        <translation>半径</translation>
    </message>
    <message>
        <source>Line</source>
        <translation>行</translation>
    </message>
    <message>
        <source>Direction</source>
        <translation>方向</translation>
    </message>
    <message>
        <source>Residual</source>
        <translation>残差</translation>
    </message>
    <message>
        <source>Surface Z</source>
        <translation>表面 Z</translation>
    </message>
    <message>
        <source>Active length</source>
        <translation>有效长度（对刀）</translation>
    </message>
    <message>
        <source>Nominal length</source>
        <translation>名义长度</translation>
    </message>
    <message>
        <source>Mean trigger Z</source>
        <translation>平均触发 Z</translation>
    </message>
    <message>
        <source>Range of trigger Z</source>
        <translation>触发 Z 极差</translation>
    </message>
    <message>
        <source>Effective length</source>
        <translation>有效长度</translation>
    </message>
    <message>
        <source>Wear</source>
        <translation>磨损</translation>
    </message>
    <message>
        <source>Interpolation period</source>
        <translation>插补周期</translation>
    </message>
    <message>
        <source>Group</source>
        <translation>组</translation>
    </message>
    <message>
        <source>Axis</source>
        <translation>轴</translation>
    </message>
    <message>
        <source>Delay</source>
        <translation>延迟时间</translation>
    </message>
    <message>
        <source>Position at zero feed</source>
        <translation>零进给时的位置</translation>
    </message>
    <message>
        <source>Lag [cycles]</source>
        <translation>滞后 [周期]</translation>
    </message>
    <message>
        <source>Compensation lag [cycles]</source>
        <translation>补偿滞后 [周期]</translation>
    </message>
    <message>
        <source>Residual (2σ)</source>
        <translation>残差 (2σ)</translation>
    </message>
    <message>
        <source>Feed</source>
        <translation>进给率</translation>
    </message>
    <message>
        <source>Mean deviation</source>
        <translation>平均偏差</translation>
    </message>
    <message>
        <source>Fitted deviation</source>
        <translation>拟合偏差</translation>
    </message>
    <message>
        <source>Range</source>
        <translation>极差</translation>
    </message>
    <message>
        <source>Measured</source>
        <translation>测得值</translation>
    </message>
    <message>
        <source>Axis X</source>
        <translation>轴线 X</translation>
    </message>
    <message>
        <source>Axis Y</source>
        <translation>轴线 Y</translation>
    </message>
    <message>
        <source>Angle</source>
        <translation>角度</translation>
    </message>
    <message>
        <source>Point</source>
        <translation>点号</translation>
    </message>
    <message>
        <source>Deviation</source>
        <translation>偏差</translation>
    </message>
    <message>
        <source>Direct deviation</source>
        <translation>直接偏差</translation>
    </message>
    <message>
        <source>System error</source>
        <translation>系统误差</translation>
    </message>
    <message>
        <source>C-axis uncertainty</source>
        <translation>C 轴不确定度</translation>
    </message>
    <message>
        <source>Tolerance</source>
        <translation>公差</translation>
    </message>
    <message>
        <source>Test part (on the machine)</source>
        <translation>被测零件（机上）</translation>
    </message>
    <message>
        <source>pasted</source>
        <translation>粘贴</translation>
    </message>
    <message>
        <source>deg</source>
        <translation>°</translation>
    </message>
    <message>
        <source>rad</source>
        <translation>rad</translation>
    </message>
    <message>
        <source>%1: statistics</source>
        <extracomment>%1 a section of the report, e.g. Points</extracomment>
        <translation>%1：统计</translation>
    </message>
    <message>
        <source>%1: the %2 largest of %4 by |%3|</source>
        <extracomment>%1 a section (Points), %2 how many rows, %3 the column, %4 how many in all</extracomment>
        <translation>%1：%4 个中 |%3| 最大的 %2 个</translation>
    </message>
    <message>
        <source>No warnings.</source>
        <translation>无警告。</translation>
    </message>
    <message>
        <source>Error</source>
        <translation>错误</translation>
    </message>
    <message>
        <source>Warning</source>
        <translation>警示</translation>
    </message>
    <message>
        <source>Note</source>
        <translation>提示</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <extracomment>%1 the severity (Error, Warning, Note), %2 the warning&apos;s title</extracomment>
        <translation>%1：%2</translation>
    </message>
    <message>
        <source>Warnings</source>
        <translation>警告</translation>
    </message>
    <message>
        <source>Out of tol.</source>
        <translation>超差</translation>
    </message>
    <message>
        <source>identified</source>
        <translation>已识别</translation>
    </message>
    <message>
        <source>not identified</source>
        <translation>未识别</translation>
    </message>
</context>
<context>
    <name>UncertaintyBudget</name>
    <message>
        <source>Scan wait of the skip input</source>
        <translation>跳跃输入的扫描等待</translation>
    </message>
    <message>
        <source>Probe repeatability</source>
        <translation>测头重复性</translation>
    </message>
    <message>
        <source>Probe lobing</source>
        <translation>测头各向异性</translation>
    </message>
    <message>
        <source>Calibration artefact</source>
        <translation>校准标准器</translation>
    </message>
    <message>
        <source>Machine positioning repeatability</source>
        <translation>机床定位重复性</translation>
    </message>
    <message>
        <source>Thermal drift</source>
        <translation>热漂移</translation>
    </message>
    <message>
        <source>full range, ÷ √12</source>
        <translation>全范围，÷ √12</translation>
    </message>
    <message>
        <source>± half-width, ÷ √3</source>
        <translation>± 半宽，÷ √3</translation>
    </message>
    <message>
        <source>2σ or k = 2, ÷ 2</source>
        <translation>2σ 或 k = 2，÷ 2</translation>
    </message>
    <message>
        <source>%1, mean of %2</source>
        <extracomment>%1 how the value is stated, %2 the number of repeated touches averaged</extracomment>
        <translation>%1，%2 次平均</translation>
    </message>
    <message>
        <source>Term</source>
        <translation>预算项</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>数值</translation>
    </message>
    <message>
        <source>Stated as</source>
        <translation>给定方式</translation>
    </message>
    <message>
        <source>Standard uncertainty</source>
        <translation>标准不确定度</translation>
    </message>
    <message>
        <source>Share</source>
        <translation>占比</translation>
    </message>
    <message>
        <source>Combined (root sum of squares)</source>
        <translation>合成（平方和的平方根）</translation>
    </message>
    <message>
        <source>Expanded uncertainty, k = 2</source>
        <translation>扩展不确定度，k = 2</translation>
    </message>
</context>
<context>
    <name>Warning</name>
    <message>
        <source>Overtravel near or over the limit</source>
        <translation>过行程接近或超过极限</translation>
    </message>
    <message>
        <source>Backoff too small</source>
        <translation>回退距离过小</translation>
    </message>
    <message>
        <source>Backoff longer than needed</source>
        <translation>回退距离超出需要</translation>
    </message>
    <message>
        <source>Touch while accelerating</source>
        <translation>加速过程中触测</translation>
    </message>
    <message>
        <source>Feedrate beyond the knee</source>
        <translation>进给率超过拐点</translation>
    </message>
    <message>
        <source>Uncertainty over the target</source>
        <translation>不确定度超过目标</translation>
    </message>
    <message>
        <source>Calibration feed differs</source>
        <translation>标定进给率不同</translation>
    </message>
    <message>
        <source>Overtravel %1 is %2 % of the probe&apos;s %3 limit: the probe or stylus will be damaged; lower the feed or the delays</source>
        <translation>过行程 %1 为测头极限 %3 的 %2 %：测头或测针将被损坏；请降低进给率或延迟</translation>
    </message>
    <message>
        <source>Overtravel %1 is %2 % of the probe&apos;s %3 limit: little margin left for the stylus</source>
        <translation>过行程 %1 为测头极限 %3 的 %2 %：测针余量很小</translation>
    </message>
    <message>
        <source>Backoff %1 is more than the recommended %2 and wastes %3 per cycle</source>
        <translation>回退距离 %1 大于推荐值 %2，每个循环浪费 %3</translation>
    </message>
    <message>
        <source>Second touch starts closer than the distance needed to reach its feed: it triggers at %1 instead of %2, an error of %3 against a calibration at full feed</source>
        <translation>第二次触测的起点比达到其进给率所需的距离更近：触发速度为 %1 而非 %2，相对于全速标定误差为 %3</translation>
    </message>
    <message>
        <source>First touch starts closer than the distance needed to reach its feed: it triggers at %1 instead of %2, an error of %3 against a calibration at full feed</source>
        <translation>第一次触测的起点比达到其进给率所需的距离更近：触发速度为 %1 而非 %2，相对于全速标定误差为 %3</translation>
    </message>
    <message>
        <source>Probing feed %1 is beyond the knee at %2 and no faster: the cycle takes %3 longer, with more overtravel and uncertainty</source>
        <translation>探测进给率 %1 超过拐点 %2 且并不更快：循环多用 %3，过行程和不确定度也更大</translation>
    </message>
    <message>
        <source>Uncertainty %1 exceeds the target %2</source>
        <translation>不确定度 %1 超过目标 %2</translation>
    </message>
    <message>
        <source>Measuring at %1 but calibrated at %2: the delay travel shifts the measured value by %3; calibrate at the measuring feed</source>
        <translation>以 %1 测量但在 %2 下标定：延迟行程使测量值偏移 %3；请在测量进给率下标定</translation>
    </message>
    <message>
        <source>Probing feed %1 is beyond the knee at %2: the extra feed saves only %3 (under %4) while overtravel and uncertainty grow</source>
        <translation>探测进给率 %1 超过拐点 %2：额外的进给率只节省 %3（不到 %4），而过行程和不确定度都在增大</translation>
    </message>
    <message>
        <source>The fastest cycle lies at the highest feed searched, %1: the knee at %2 depends on that range; search faster feeds too</source>
        <translation>最快的循环位于所查找的最高进给率 %1：拐点 %2 取决于该范围；请同时查找更高的进给率</translation>
    </message>
    <message>
        <source>The fastest cycle lies at the lowest feed searched, %1: the knee at %2 depends on that range; search slower feeds too</source>
        <translation>最快的循环位于所查找的最低进给率 %1：拐点 %2 取决于该范围；请同时查找更低的进给率</translation>
    </message>
    <message>
        <source>Fastest cycle at the end of the range</source>
        <translation>最快循环位于范围端点</translation>
    </message>
    <message>
        <source>Backoff %1 from the recorded trigger position is less than the recommended %2 (that position&apos;s distance past the surface plus room to reseat and to reach the measuring feed): the probe may not reseat before the second touch</source>
        <translation>从记录的触发位置起的回退距离 %1 小于推荐值 %2（该位置越过表面的距离加上复位和加速到测量进给率所需的距离）：第二次触测前测头可能尚未复位</translation>
    </message>
    <message>
        <source>Backoff %1 from where the probe stopped is less than the recommended %2 (the first touch&apos;s overtravel plus room to reseat and to reach the measuring feed): the probe may not reseat before the second touch</source>
        <translation>从停止处起的回退距离 %1 小于推荐值 %2（第一次触测的过行程加上复位和加速到测量进给率所需的距离）：第二次触测前测头可能尚未复位</translation>
    </message>
    <message>
        <source>No probing feed from %1 to %2 gives a valid cycle: the overtravel reaches the probe&apos;s limit even at %1, so there is no knee; shorten the delays or use a probe with more overtravel</source>
        <translation>从 %1 到 %2 没有任何探测进给率能得到有效循环：即使在 %1 时过行程也已达到测头极限，因此没有拐点；请缩短延迟或选用允许过行程更大的测头</translation>
    </message>
    <message>
        <source>No valid feed</source>
        <translation>没有有效进给率</translation>
    </message>
    <message>
        <source>Measuring feed %1 is over the probe&apos;s rated maximum %2: it may not trigger reliably or may be damaged; measure at %2 or slower</source>
        <translation>测量进给率 %1 超过测头额定最大值 %2：测头可能无法可靠触发或损坏；请以 %2 或更慢的速度测量</translation>
    </message>
    <message>
        <source>Probing feed %1 is over the probe&apos;s rated maximum %2: it may not trigger reliably or may be damaged; probe at %2 or slower</source>
        <translation>探测进给率 %1 超过测头额定最大值 %2：测头可能无法可靠触发或损坏；请以 %2 或更慢的速度探测</translation>
    </message>
    <message>
        <source>Start distance %1 is inside the part&apos;s position uncertainty %2: where the part lies nearer, the probe starts in contact with it; start at least %3 out (the uncertainty plus the distance to reach the probing feed)</source>
        <translation>起始距离 %1 位于零件位置不确定度 %2 之内：零件较近时，测头起始即与其接触；起始距离至少为 %3（不确定度加上达到探测进给率所需的距离）</translation>
    </message>
    <message>
        <source>Start distance %1 covers the part&apos;s position uncertainty %2 but not the distance to reach the probing feed after it: where the part lies nearer, the touch is made while accelerating; start at least %3 out</source>
        <translation>起始距离 %1 覆盖了零件位置不确定度 %2，但不足以在其后达到探测进给率：零件较近时，触测发生在加速过程中；起始距离至少为 %3</translation>
    </message>
    <message>
        <source>Feed over the probe&apos;s rating</source>
        <translation>进给率超过测头额定值</translation>
    </message>
    <message>
        <source>Start within the part&apos;s position uncertainty</source>
        <translation>起点位于零件位置不确定度内</translation>
    </message>
    <message>
        <source>The second touch&apos;s search ends %1 past where the first touch stopped, before its own stop %2 past the surface: it is braking when it touches, triggers below the measuring feed and stops at the search end; search at least %2 past the surface</source>
        <translation>第二次触测的搜索在第一次触测停止位置之后 %1 处结束，早于其自身在表面之后 %2 的停止位置：触碰时已在减速，触发速度低于测量进给率并停在搜索终点；请至少搜索到表面之后 %2</translation>
    </message>
    <message>
        <source>The search ends %1 past the farthest place the surface can be, before the first touch&apos;s stop %2 past it: the axis is braking when it touches, triggers below the feed and stops at the search end; search at least %2 past the surface</source>
        <translation>搜索在表面可能所在的最远位置之后 %1 处结束，早于第一次触测在其之后 %2 的停止位置：触碰时轴已在减速，触发速度低于进给率并停在搜索终点；请至少搜索到表面之后 %2</translation>
    </message>
    <message>
        <source>Search ends before the stop</source>
        <translation>搜索在停止位置之前结束</translation>
    </message>
    <message>
        <source>A protected move at the positioning feed %1 that meets an obstruction stops %2 past it, %3 % of the probe&apos;s %4 limit: the stylus would be overrun; lower the positioning feed</source>
        <translation>以定位进给率 %1 进行的受保护移动碰到障碍物后停在其之后 %2，为测头 %4 极限的 %3 %：测针将被过度压入；请降低定位进给率</translation>
    </message>
    <message>
        <source>A protected move at the positioning feed %1 that meets an obstruction stops %2 past it, %3 % of the probe&apos;s %4 limit: little margin left for the stylus</source>
        <translation>以定位进给率 %1 进行的受保护移动碰到障碍物后停在其之后 %2，为测头 %4 极限的 %3 %：测针余量所剩无几</translation>
    </message>
    <message>
        <source>Protected moves near the overtravel limit</source>
        <translation>受保护移动接近过行程极限</translation>
    </message>
    <message>
        <source>Overtravel %1 at %5 % feed override is %2 % of the probe&apos;s %3 limit: the probe or stylus will be damaged; lower the feed or the delays</source>
        <translation>%5 % 进给倍率下过行程 %1，为测头极限 %3 的 %2 %：测头或测针将损坏；请降低进给或延迟</translation>
    </message>
    <message>
        <source>Overtravel %1 at %5 % feed override is %2 % of the probe&apos;s %3 limit: little margin left for the stylus</source>
        <translation>%5 % 进给倍率下过行程 %1，为测头极限 %3 的 %2 %：测针余量很小</translation>
    </message>
    <message>
        <source>A protected move at the positioning feed %1 and %5 % feed override that meets an obstruction stops %2 past it, %3 % of the probe&apos;s %4 limit: the stylus would be overrun; lower the positioning feed</source>
        <translation>以定位进给 %1、%5 % 进给倍率执行的受保护移动若遇到障碍物，会停在其后 %2 处，为测头极限 %4 的 %3 %：测针将被过冲；请降低定位进给</translation>
    </message>
    <message>
        <source>A protected move at the positioning feed %1 and %5 % feed override that meets an obstruction stops %2 past it, %3 % of the probe&apos;s %4 limit: little margin left for the stylus</source>
        <translation>以定位进给 %1、%5 % 进给倍率执行的受保护移动若遇到障碍物，会停在其后 %2 处，为测头极限 %4 的 %3 %：测针余量很小</translation>
    </message>
    <message>
        <source>No probing feed from %1 to %2 is reached: the first touch meets the surface before it reaches even %1, so there is no knee; start the touch farther out</source>
        <translation>从 %1 到 %2 的探测进给率均未达到：第一次触测在达到 %1 之前就已接触表面，因此没有拐点；请将触测起点移远</translation>
    </message>
</context>
<context>
    <name>probecycle::ui::CalibrationTab</name>
    <message>
        <source>Ring gauge: touches at 0° and 180°</source>
        <translation>环规：0° 和 180° 下的触测</translation>
    </message>
    <message>
        <source>Paste the trigger positions the control recorded, or import a CSV file. Columns &lt;code&gt;orientation_deg,x_mm,y_mm&lt;/code&gt;; spindle oriented at 0° and at 180°, 3 or more points each (typically X+, X−, Y+, Y−).</source>
        <translation>粘贴数控系统记录的触发位置，或导入 CSV 文件。列为 &lt;code&gt;orientation_deg,x_mm,y_mm&lt;/code&gt;；主轴定向于 0° 和 180°，每个方向 3 个或更多点（通常为 X+、X−、Y+、Y−）。</translation>
    </message>
    <message>
        <source>(example)</source>
        <translation>（示例）</translation>
    </message>
    <message>
        <source>Gauge diameter</source>
        <translation>环规直径</translation>
    </message>
    <message>
        <source>The calibrated diameter of the ring gauge, from its certificate.</source>
        <translation>环规的标定直径，取自其证书。</translation>
    </message>
    <message>
        <source>Runout limit</source>
        <translation>跳动极限</translation>
    </message>
    <message>
        <source>Warn when the stylus runout (eccentricity) is larger.</source>
        <translation>测针跳动（偏心）大于此值时警告。</translation>
    </message>
    <message>
        <source>Residual limit</source>
        <translation>残差极限</translation>
    </message>
    <message>
        <source>Warn when a point lies further than this off its fitted circle: dirt, a bad touch or a loose gauge.</source>
        <translation>当某点偏离其拟合圆超过此值时警告：污物、触测不良或环规松动。</translation>
    </message>
    <message>
        <source>Length from a surface of known Z</source>
        <translation>由已知 Z 的表面确定长度</translation>
    </message>
    <message>
        <source>Surface Z</source>
        <translation>表面 Z</translation>
    </message>
    <message>
        <source>The known Z of the gauge top, sphere or block, set by a reference tool.</source>
        <translation>由基准刀具确定的环规顶面、标准球或量块的已知 Z 值。</translation>
    </message>
    <message>
        <source>Trigger Z</source>
        <translation>触发 Z</translation>
    </message>
    <message>
        <source>The Z the control recorded at the touch; several touches separated by spaces or semicolons.</source>
        <translation>数控系统在触测时记录的 Z；多次触测用空格或分号分隔。</translation>
    </message>
    <message>
        <source>Active length</source>
        <translation>当前长度补偿</translation>
    </message>
    <message>
        <source>The tool length offset active while probing (0 when none).</source>
        <translation>测量时生效的刀具长度补偿（无则为 0）。</translation>
    </message>
    <message>
        <source>Nominal length</source>
        <translation>名义长度</translation>
    </message>
    <message>
        <source>The probe&apos;s nominal length, to express the result as wear (0 = none).</source>
        <translation>测头的名义长度，用于将结果表示为磨损值（0 = 不用）。</translation>
    </message>
    <message>
        <source>none</source>
        <translation>无</translation>
    </message>
    <message>
        <source>Radial deviations:</source>
        <translation>径向偏差：</translation>
    </message>
    <message>
        <source>Magnified, automatic</source>
        <translation>自动放大</translation>
    </message>
    <message>
        <source>True scale</source>
        <translation>实际比例</translation>
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
        <translation>0° 拟合圆</translation>
    </message>
    <message>
        <source>Circle at 180°</source>
        <translation>180° 拟合圆</translation>
    </message>
    <message>
        <source>Gauge centre</source>
        <translation>环规中心</translation>
    </message>
    <message>
        <source>Result</source>
        <translation>结果</translation>
    </message>
    <message>
        <source>Stylus runout</source>
        <translation>测针跳动</translation>
    </message>
    <message>
        <source>Effective ball radius</source>
        <translation>有效测球半径</translation>
    </message>
    <message>
        <source>Radius by direction</source>
        <translation>各方向半径</translation>
    </message>
    <message>
        <source>Largest residual</source>
        <translation>最大残差</translation>
    </message>
    <message>
        <source>Points</source>
        <translation>点数</translation>
    </message>
    <message>
        <source>Warnings</source>
        <translation>警告</translation>
    </message>
    <message>
        <source>No warnings.</source>
        <translation>无警告。</translation>
    </message>
    <message>
        <source>Export CSV report…</source>
        <translation>导出 CSV 报告…</translation>
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
        <translation>未知：只有一个方向</translation>
    </message>
    <message>
        <source>centre %1, %2; radius %3</source>
        <translation>中心 %1, %2；半径 %3</translation>
    </message>
    <message>
        <source>no points</source>
        <translation>无点</translation>
    </message>
    <message>
        <source>%1 at 0°, %2 at 180°; gauge %3</source>
        <translation>0° 下 %1 点，180° 下 %2 点；环规 %3</translation>
    </message>
    <message>
        <source>Radial deviations magnified × %1</source>
        <translation>径向偏差放大 × %1</translation>
    </message>
    <message>
        <source>No fit yet</source>
        <translation>尚未拟合</translation>
    </message>
    <message>
        <source>Trigger Z: “%1” is not a number.</source>
        <translation>触发 Z：“%1”不是数字。</translation>
    </message>
    <message>
        <source>Effective length: &lt;b&gt;%1&lt;/b&gt;</source>
        <translation>有效长度：&lt;b&gt;%1&lt;/b&gt;</translation>
    </message>
    <message>
        <source>Wear: %1</source>
        <translation>磨损：%1</translation>
    </message>
    <message>
        <source>Enter the trigger Z of one or more touches.</source>
        <translation>请输入一次或多次触测的触发 Z。</translation>
    </message>
    <message>
        <source>Nothing to export: fit the ring points or enter a length first.</source>
        <translation>没有可导出的内容：请先拟合环规点或输入长度。</translation>
    </message>
    <message>
        <source>Import ring gauge points</source>
        <translation>导入环规测点</translation>
    </message>
    <message>
        <source>Export calibration report</source>
        <translation>导出标定报告</translation>
    </message>
    <message>
        <source>Spindle at 0°</source>
        <translation>主轴 0°</translation>
    </message>
    <message>
        <source>Spindle at 180°</source>
        <translation>主轴 180°</translation>
    </message>
    <message>
        <source>%1 in all</source>
        <translation>共 %1</translation>
    </message>
    <message>
        <source>Touches: %1, spread %2</source>
        <translation>触测：%1 次，分散 %2</translation>
    </message>
    <message>
        <source>The ring-gauge calibration as a program for your control (LinuxCNC, grbl, Fanuc, Haas, Mitsubishi, Siemens), with the plan that the import of its log needs.</source>
        <translation>将环规标定生成为适用于您的数控系统（LinuxCNC, grbl, Fanuc, Haas, Mitsubishi, Siemens）的程序，并附带导入其日志所需的计划。</translation>
    </message>
    <message>
        <source>What the control recorded while it ran the program, read with the program&apos;s plan into the points and fitted.</source>
        <translation>数控系统运行程序时记录的内容，按程序的计划读入测点并拟合。</translation>
    </message>
    <message>
        <source>e.g. %1; %2</source>
        <translation>例如 %1; %2</translation>
    </message>
</context>
<context>
    <name>probecycle::ui::ComparisonTab</name>
    <message>
        <source>Files and setup</source>
        <translation>文件与设置</translation>
    </message>
    <message>
        <source>CSV files with a header row, in the plan&apos;s order: the plan &lt;code&gt;x_mm,y_mm,z_mm,i,j,k&lt;/code&gt; (outward unit normal), points &lt;code&gt;x_mm,y_mm,z_mm&lt;/code&gt; (or DMIS &lt;code&gt;PTMEAS/CART&lt;/code&gt;), the block &lt;code&gt;face,x_mm,y_mm,z_mm&lt;/code&gt; with faces A, B, C.</source>
        <translation>带表头行的 CSV 文件，按检测计划的顺序：检测计划为 &lt;code&gt;x_mm,y_mm,z_mm,i,j,k&lt;/code&gt;（外法向单位矢量），测点为 &lt;code&gt;x_mm,y_mm,z_mm&lt;/code&gt;（或 DMIS &lt;code&gt;PTMEAS/CART&lt;/code&gt;），试块为 &lt;code&gt;face,x_mm,y_mm,z_mm&lt;/code&gt;，面为 A、B、C。</translation>
    </message>
    <message>
        <source>Inspection plan</source>
        <translation>检测计划</translation>
    </message>
    <message>
        <source>Reference part, CMM points</source>
        <translation>参考件，三坐标测量机测点</translation>
    </message>
    <message>
        <source>Test part, on-machine points at C = 0</source>
        <translation>被测件，C = 0 时的在机测量点</translation>
    </message>
    <message>
        <source>Reference part, on-machine points after the turn</source>
        <translation>参考件，旋转后的在机测量点</translation>
    </message>
    <message>
        <source>Block at C = 0 (optional)</source>
        <translation>C = 0 时的试块（可选）</translation>
    </message>
    <message>
        <source>Block after the turn (optional)</source>
        <translation>旋转后的试块（可选）</translation>
    </message>
    <message>
        <source>Nominal points and outward unit normals (the side the probe comes from), in machine coordinates at the measuring position (C = 0).</source>
        <translation>名义点及外法向单位矢量（测头接近的一侧），为测量位置（C = 0）下的机床坐标。</translation>
    </message>
    <message>
        <source>The reference part as the CMM measured it, one point per plan point, in the plan&apos;s coordinates.</source>
        <translation>三坐标测量机测得的参考件，每个计划点对应一个测点，采用检测计划的坐标。</translation>
    </message>
    <message>
        <source>The test part probed on the machine along the plan, C at 0.</source>
        <translation>按检测计划在机床上测量的被测件，C轴位于 0。</translation>
    </message>
    <message>
        <source>The reference part probed along the same plan after C turned by the angle: at the same place of the machine as the test part.</source>
        <translation>C轴转过比较角度后，按同一检测计划测量的参考件：位于机床上与被测件相同的位置。</translation>
    </message>
    <message>
        <source>Three faces of a block&apos;s corner, touched at C = 0: they give the C axis&apos;s six errors. Without the block the C axis is taken as exact.</source>
        <translation>在 C = 0 时触测的试块某一角的三个面：由此得到 C轴的六项误差。不使用试块时，C轴视为无误差。</translation>
    </message>
    <message>
        <source>The same three faces touched after the turn.</source>
        <translation>旋转后触测的同样三个面。</translation>
    </message>
    <message>
        <source>Choose a file…</source>
        <translation>选择文件…</translation>
    </message>
    <message>
        <source>C axis X</source>
        <translation>C轴 X</translation>
    </message>
    <message>
        <source>Where the C axis is, in machine X.</source>
        <translation>C轴在机床 X 方向上的位置。</translation>
    </message>
    <message>
        <source>C axis Y</source>
        <translation>C轴 Y</translation>
    </message>
    <message>
        <source>Where the C axis is, in machine Y.</source>
        <translation>C轴在机床 Y 方向上的位置。</translation>
    </message>
    <message>
        <source>Comparison angle</source>
        <translation>比较角度</translation>
    </message>
    <message>
        <source>How far C turns between the two measurements (180° for parts clamped opposite each other).</source>
        <translation>两次测量之间 C轴的转角（两件相对装夹时为 180°）。</translation>
    </message>
    <message>
        <source>Tolerance (±)</source>
        <translation>公差 (±)</translation>
    </message>
    <message>
        <source>Half-width of the tolerance band about the nominal surface.</source>
        <translation>名义曲面两侧公差带的半宽。</translation>
    </message>
    <message>
        <source>Run</source>
        <translation>运行</translation>
    </message>
    <message>
        <source>Simulate example data</source>
        <translation>模拟示例数据</translation>
    </message>
    <message>
        <source>Write a simulated data set with a known truth (truth.csv) to a folder and run it.</source>
        <translation>将真值已知（truth.csv）的模拟数据集写入文件夹并运行。</translation>
    </message>
    <message>
        <source>Open project…</source>
        <translation>打开项目…</translation>
    </message>
    <message>
        <source>Save project…</source>
        <translation>保存项目…</translation>
    </message>
    <message>
        <source>Deviation of the test part</source>
        <translation>被测件偏差</translation>
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
        <translation>偏差：直接在机测量与比较测量</translation>
    </message>
    <message>
        <source>Deviation [%1]</source>
        <translation>偏差 [%1]</translation>
    </message>
    <message>
        <source>Points</source>
        <translation>点数</translation>
    </message>
    <message>
        <source>Direct OMM</source>
        <translation>直接在机测量</translation>
    </message>
    <message>
        <source>Comparison</source>
        <translation>比较测量</translation>
    </message>
    <message>
        <source>Tolerance</source>
        <translation>公差</translation>
    </message>
    <message>
        <source>Result</source>
        <translation>结果</translation>
    </message>
    <message>
        <source>C-axis errors</source>
        <translation>C轴误差</translation>
    </message>
    <message>
        <source>Error</source>
        <translation>误差</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>值</translation>
    </message>
    <message>
        <source>Uncertainty</source>
        <translation>不确定度</translation>
    </message>
    <message>
        <source>Min</source>
        <translation>最小</translation>
    </message>
    <message>
        <source>Max</source>
        <translation>最大</translation>
    </message>
    <message>
        <source>RMS</source>
        <translation>RMS</translation>
    </message>
    <message>
        <source>Out of tol.</source>
        <translation>超差</translation>
    </message>
    <message>
        <source>Warnings</source>
        <translation>警告</translation>
    </message>
    <message>
        <source>No warnings.</source>
        <translation>无警告。</translation>
    </message>
    <message>
        <source>Points, worst first</source>
        <translation>测点（最差的在前）</translation>
    </message>
    <message>
        <source>Point</source>
        <translation>点号</translation>
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
        <translation>偏差</translation>
    </message>
    <message>
        <source>System error</source>
        <translation>系统误差</translation>
    </message>
    <message>
        <source>Export report…</source>
        <translation>导出报告…</translation>
    </message>
    <message>
        <source>The block is needed at both angles: choose both block files, or neither.</source>
        <translation>两个角度下都需要试块数据：请选择两个试块文件，或都不选。</translation>
    </message>
    <message>
        <source>Cannot make the folder %1.</source>
        <translation>无法创建文件夹 %1。</translation>
    </message>
    <message>
        <source>Nothing to export: run the comparison first.</source>
        <translation>没有可导出的内容：请先运行比较测量。</translation>
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
        <translation>µrad</translation>
    </message>
    <message>
        <source>not identified</source>
        <translation>未辨识</translation>
    </message>
    <message>
        <source>unknown</source>
        <translation>未知</translation>
    </message>
    <message>
        <source>below %1 %2 (out)</source>
        <translation>低于 %1 %2（超差）</translation>
    </message>
    <message>
        <source>above +%1 %2 (out)</source>
        <translation>高于 +%1 %2（超差）</translation>
    </message>
    <message>
        <source>%1 to %2 %3</source>
        <translation>%1 至 %2 %3</translation>
    </message>
    <message>
        <source>Point files (*.csv *.dmi *.dmis *.txt);;All files (*)</source>
        <translation>测点文件 (*.csv *.dmi *.dmis *.txt);;所有文件 (*)</translation>
    </message>
    <message>
        <source>Open comparison project</source>
        <translation>打开比较测量项目</translation>
    </message>
    <message>
        <source>Comparison projects (*.json)</source>
        <translation>比较测量项目 (*.json)</translation>
    </message>
    <message>
        <source>Save comparison project</source>
        <translation>保存比较测量项目</translation>
    </message>
    <message>
        <source>Export comparison report</source>
        <translation>导出比较测量报告</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>CSV 文件 (*.csv)</translation>
    </message>
    <message>
        <source>Choose a file for “%1”.</source>
        <translation>请为“%1”选择文件。</translation>
    </message>
    <message>
        <source>Direct OMM against the comparison [%1]</source>
        <translation>直接在机测量与比较测量对比 [%1]</translation>
    </message>
</context>
<context>
    <name>probecycle::ui::CompensationPanel</name>
    <message>
        <source>Uncompensated</source>
        <translation>未补偿</translation>
    </message>
    <message>
        <source>Naive v·τ</source>
        <translation>简单 v·τ</translation>
    </message>
    <message>
        <source>Cycle lag (real increments)</source>
        <translation>周期滞后（实际增量）</translation>
    </message>
    <message>
        <source>Timestamp interpolation</source>
        <translation>时间戳插值</translation>
    </message>
    <message>
        <source>Real increments</source>
        <translation>实际增量</translation>
    </message>
    <message>
        <source>Timestamp</source>
        <translation>时间戳</translation>
    </message>
    <message>
        <source>Feed</source>
        <translation>进给率</translation>
    </message>
    <message>
        <source>Interpolation period</source>
        <translation>插补周期</translation>
    </message>
    <message>
        <source>Lag</source>
        <translation>滞后</translation>
    </message>
    <message>
        <source>Speed at the trigger</source>
        <translation>触发时速度</translation>
    </message>
    <message>
        <source>Direction of travel</source>
        <translation>行程方向</translation>
    </message>
    <message>
        <source>Trigger phase in its cycle</source>
        <translation>触发在其周期内的相位</translation>
    </message>
    <message>
        <source>Encoder counts per mm</source>
        <translation>每毫米编码器计数</translation>
    </message>
    <message>
        <source>Encoder counter width</source>
        <translation>编码器计数器位数</translation>
    </message>
    <message>
        <source>Delay for v·τ</source>
        <translation>v·τ 所用的延迟</translation>
    </message>
    <message>
        <source>Compensation of the trigger position</source>
        <translation>触发位置的补偿</translation>
    </message>
    <message>
        <source>The programmed probing feed.</source>
        <translation>编程的探测进给率。</translation>
    </message>
    <message>
        <source>The control&apos;s interpolation cycle.</source>
        <translation>数控系统的插补周期。</translation>
    </message>
    <message>
        <source>Cycles between the end of the trigger&apos;s cycle and the recorded position; the delay-stability test above measures it.</source>
        <translation>从触发所在周期结束到记录位置之间的周期数；由上面的延迟稳定性测试测得。</translation>
    </message>
    <message>
        <source> cycles</source>
        <translation> 个周期</translation>
    </message>
    <message>
        <source>Touch</source>
        <translation>触测</translation>
    </message>
    <message>
        <source>At constant speed, or while the axis is braking.</source>
        <translation>匀速时，或轴正在制动时。</translation>
    </message>
    <message>
        <source>At constant speed</source>
        <translation>匀速</translation>
    </message>
    <message>
        <source>While braking</source>
        <translation>制动中</translation>
    </message>
    <message>
        <source>While braking: the speed at the trigger, in % of the feed.</source>
        <translation>制动中：触发时的速度，以进给率的 % 表示。</translation>
    </message>
    <message>
        <source>Take period and lag from the fit</source>
        <translation>采用拟合得到的周期和滞后</translation>
    </message>
    <message>
        <source>Machine dynamics from the scenario. While braking, v·τ assumes the feed through the whole delay and over-corrects; the real increments of the last cycles stay within one cycle&apos;s travel.</source>
        <translation>机床动态取自场景。制动中，v·τ 假定整个延迟期间都保持进给率，因而过度修正；最近几个周期的实际增量则保持在一个周期的行程之内。</translation>
    </message>
    <message>
        <source>Error of the corrected position while braking</source>
        <translation>制动中修正后位置的误差</translation>
    </message>
    <message>
        <source>Speed at the trigger [% of the feed]</source>
        <translation>触发时速度 [进给率的 %]</translation>
    </message>
    <message>
        <source>Error [%1]</source>
        <translation>误差 [%1]</translation>
    </message>
    <message>
        <source>Method</source>
        <translation>方法</translation>
    </message>
    <message>
        <source>Position [%1]</source>
        <translation>位置 [%1]</translation>
    </message>
    <message>
        <source>Trigger at %1 mm/s, recorded %2 cycles later at %3 mm/s; v·τ uses τ = %4.</source>
        <extracomment>%1 speed at the trigger, %2 lag in cycles, %3 speed then, %4 the delay v·τ uses</extracomment>
        <translation>以 %1 mm/s 触发，%2 个周期后以 %3 mm/s 记录；v·τ 使用 τ = %4。</translation>
    </message>
    <message>
        <source>Counter roll-overs: %1.</source>
        <translation>计数器溢出：%1 次。</translation>
    </message>
    <message>
        <source>Compensated lag</source>
        <translation>补偿的滞后</translation>
    </message>
    <message>
        <source>The lag the real-increments method subtracts. Controls are often set up with a lag other than the machine&apos;s (a published study compensated 7 to 9 cycles on a machine that lagged about 10): each cycle too few leaves one cycle&apos;s travel of error. Lowest value: the lag itself.</source>
        <translation>实际增量法所减去的滞后。数控系统常按与机床实际不同的滞后设置（一项已发表的研究在滞后约 10 个周期的机床上补偿了 7 至 9 个周期）：每少补偿一个周期，就留下一个周期行程的误差。最小值：即滞后本身。</translation>
    </message>
    <message>
        <source>as the lag</source>
        <translation>同滞后</translation>
    </message>
    <message>
        <source>Real increments: error against the compensated lag</source>
        <translation>实际增量：误差与补偿滞后的关系</translation>
    </message>
    <message>
        <source>Compensated lag [cycles]</source>
        <translation>补偿的滞后 [周期]</translation>
    </message>
    <message>
        <source>Dashed: the machine&apos;s lag. Dotted: the lag compensated. The error grows by one cycle&apos;s travel for each cycle the compensation is off.</source>
        <translation>虚线：机床的滞后。点线：补偿的滞后。补偿每偏差一个周期，误差增加一个周期的行程。</translation>
    </message>
    <message>
        <source>Against the compensated lag</source>
        <translation>与补偿滞后的关系</translation>
    </message>
</context>
<context>
    <name>probecycle::ui::CycleCharts</name>
    <message>
        <source>Probing feedrate [%1]</source>
        <translation>探测进给率 [%1]</translation>
    </message>
    <message>
        <source>Cycle time vs probing feedrate</source>
        <translation>循环时间与探测进给率</translation>
    </message>
    <message>
        <source>Cycle time [%1]</source>
        <translation>循环时间 [%1]</translation>
    </message>
    <message>
        <source>Single-touch</source>
        <translation>单次触测</translation>
    </message>
    <message>
        <source>Knee</source>
        <translation>拐点</translation>
    </message>
    <message>
        <source>Time [%1]</source>
        <translation>时间 [%1]</translation>
    </message>
    <message>
        <source>Overtravel and uncertainty vs feedrate</source>
        <translation>过行程和不确定度与进给率</translation>
    </message>
    <message>
        <source>Overtravel [%1]</source>
        <translation>过行程 [%1]</translation>
    </message>
    <message>
        <source>Uncertainty, k = 2 [%1]</source>
        <translation>不确定度，k = 2 [%1]</translation>
    </message>
    <message>
        <source>Overtravel</source>
        <translation>过行程</translation>
    </message>
    <message>
        <source>Limit</source>
        <translation>极限</translation>
    </message>
    <message>
        <source>Target</source>
        <translation>目标</translation>
    </message>
    <message>
        <source>Position and speed through the cycle</source>
        <translation>循环中的位置和速度</translation>
    </message>
    <message>
        <source>Position [%1]</source>
        <translation>位置 [%1]</translation>
    </message>
    <message>
        <source>Speed [%1]</source>
        <translation>速度 [%1]</translation>
    </message>
    <message>
        <source>Position</source>
        <translation>位置</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>速度</translation>
    </message>
    <message>
        <source>Surface</source>
        <translation>表面</translation>
    </message>
    <message>
        <source>Baseline (dashed)</source>
        <translation>基准（虚线）</translation>
    </message>
    <message>
        <source>Phases: total %1</source>
        <translation>各阶段：共 %1</translation>
    </message>
    <message>
        <source>Phases</source>
        <translation>各阶段</translation>
    </message>
    <message>
        <source>Uncertainty</source>
        <translation>不确定度</translation>
    </message>
    <message>
        <source>Two-touch, best backoff</source>
        <translation>两次触测，最佳回退距离</translation>
    </message>
    <message>
        <source>This cycle</source>
        <translation>当前循环</translation>
    </message>
    <message>
        <source>1st touch</source>
        <translation>第一次触测</translation>
    </message>
    <message>
        <source>2nd touch</source>
        <translation>第二次触测</translation>
    </message>
    <message>
        <source>This cycle (invalid)</source>
        <translation>当前循环（无效）</translation>
    </message>
    <message>
        <source>Invalid</source>
        <translation>无效</translation>
    </message>
    <message>
        <source>The phases of the current cycle in time order, each row with its total time over all touches. Grey: the cycle is invalid and cannot run as set (the title and the warnings say why); its phases are what the model computes.</source>
        <translation>当前循环按时间顺序排列的各阶段，每行给出其在所有触测中的总时间。灰色：循环无效，按当前设置无法运行（原因见标题和警告）；各阶段为模型的计算结果。</translation>
    </message>
    <message>
        <source>Phases of an invalid cycle (grey): %1</source>
        <extracomment>%1: why the cycle cannot run, e.g. &quot;Backoff too small&quot;</extracomment>
        <translation>无效循环的各阶段（灰色）：%1</translation>
    </message>
    <message>
        <source>1st touch at %1 % override</source>
        <translation>第一次触测（倍率 %1 %）</translation>
    </message>
    <message>
        <source>Overtravel at %1 % override</source>
        <translation>过行程（倍率 %1 %）</translation>
    </message>
    <message>
        <source>2nd touch at %1 % override</source>
        <translation>第二次触测（倍率 %1 %）</translation>
    </message>
    <message>
        <source>This cycle&apos;s uncertainty</source>
        <translation>本循环的不确定度</translation>
    </message>
    <message>
        <source>Red: overtravel of a touch at each feed, at the highest feed override, against the probe&apos;s limit (dashed); the shaded feeds overtravel beyond it. Two-touch: the first touch solid, the second dotted; with a fixed backoff a fast first touch leaves the second too little room to brake, so the second may overtravel more. Blue, right axis: the uncertainty (k = 2) of a touch measured at each feed against the target (dotted); the dot is this cycle&apos;s, the readout&apos;s figure, at the feed of the touch that measures. Vertical lines: the probing feed and, for two-touch, the measuring feed (blue, dotted).</source>
        <translation>红色：在最高进给倍率下，各进给下触测的过行程与测头极限（虚线）的对比；阴影区域的进给过行程超过极限。两次触测：第一次触测为实线，第二次为点线；回退固定时，快速的第一次触测给第二次留下的制动空间太小，因此第二次的过行程可能更大。蓝色，右轴：在各进给下测量的一次触测的不确定度（k = 2）与目标（点线）的对比；圆点是本循环的不确定度，即读数显示的值，位于进行测量的那次触测的进给处。竖线：探测进给，以及两次触测时的测量进给（蓝色点线）。</translation>
    </message>
    <message>
        <source>Measuring feedrate</source>
        <translation>测量进给率</translation>
    </message>
    <message>
        <source>Single-touch, feed not reached</source>
        <translation>单次触测，未达进给率</translation>
    </message>
    <message>
        <source>Two-touch, feed not reached</source>
        <translation>两次触测，未达进给率</translation>
    </message>
    <message>
        <source>Cycle time of the whole cycle against the probing feed, for single-touch and two-touch with everything else as set. Vertical line: the current feed. Dot: the knee, the lowest valid feed within the knee tolerance of the best time. Grey, dashed: feeds whose cycle is invalid (overtravel over the limit, backoff too small). Dotted: feeds the first touch never reaches from its start, so the cycle is not at the feed it says (its time falls only because of that); the knee is not among them. A red dashed line: this cycle is invalid and has no cycle time (see the warnings).</source>
        <translation>整个循环的时间与探测进给率的关系，分单次触测和两次触测，其余参数按当前设置。竖线：当前进给率。圆点：拐点，即循环时间与最佳时间相差不超过拐点容差的最低有效进给率。灰色虚线：循环无效的进给率（过行程超过极限、回退距离过小）。点线：第一次触测从起点出发始终达不到的进给率，此时循环并非以所标进给率运行（循环时间下降仅因如此）；拐点不在其中。红色虚线：当前循环无效，没有循环时间（见警告）。</translation>
    </message>
    <message>
        <source>Position along the probing direction of each touch (the surface is dashed) and path speed through the whole cycle. The position line breaks during the moves between touches, which run across that direction; the speed shows them.</source>
        <translation>每次触测沿测量方向的位置（虚线为表面）以及整个循环中的轨迹速度。触测之间的移动与该方向垂直，位置曲线在这些移动期间断开；速度曲线显示这些移动。</translation>
    </message>
</context>
<context>
    <name>probecycle::ui::DelayFitPanel</name>
    <message>
        <source>Delay from touches at several feeds (delay-stability test)</source>
        <translation>由多个进给率下的触测求延迟（延迟稳定性测试）</translation>
    </message>
    <message>
        <source>Touch the same surface several times at each of several feeds, per axis and direction, starting far enough out to be at full speed. Paste or import the positions: &lt;code&gt;axis,direction,feed_mm_min,measured_mm&lt;/code&gt; (direction +1 or −1, of travel).</source>
        <translation>按轴和方向，在多个进给率下对同一表面各触测数次，起点要足够远以保证全速。粘贴或导入位置：&lt;code&gt;axis,direction,feed_mm_min,measured_mm&lt;/code&gt;（direction 为运动方向 +1 或 −1）。</translation>
    </message>
    <message>
        <source>(example)</source>
        <translation>（示例）</translation>
    </message>
    <message>
        <source>Interpolation period</source>
        <translation>插补周期</translation>
    </message>
    <message>
        <source>The control&apos;s interpolation cycle, to express the delay in cycles (optional).</source>
        <translation>数控系统的插补周期，用于以周期数表示延迟（可选）。</translation>
    </message>
    <message>
        <source>none</source>
        <translation>无</translation>
    </message>
    <message>
        <source>Measured minus zero-speed position, against feed</source>
        <translation>测量值减零速位置，与进给率的关系</translation>
    </message>
    <message>
        <source>Feed [%1]</source>
        <translation>进给率 [%1]</translation>
    </message>
    <message>
        <source>Deviation [%1]</source>
        <translation>偏差 [%1]</translation>
    </message>
    <message>
        <source>Group / feed</source>
        <translation>组 / 进给率</translation>
    </message>
    <message>
        <source>Delay τ</source>
        <translation>延迟 τ</translation>
    </message>
    <message>
        <source>Cycles</source>
        <translation>周期数</translation>
    </message>
    <message>
        <source>p₀ / mean</source>
        <translation>p₀ / 平均</translation>
    </message>
    <message>
        <source>2σ / range</source>
        <translation>2σ / 极差</translation>
    </message>
    <message>
        <source>n</source>
        <translation>n</translation>
    </message>
    <message>
        <source>The total delay: the slope of the line over the feeds.</source>
        <translation>总延迟：各进给率拟合直线的斜率。</translation>
    </message>
    <message>
        <source>The delay in interpolation cycles (with the period given).</source>
        <translation>以插补周期数表示的延迟（需给定周期）。</translation>
    </message>
    <message>
        <source>Group: the zero-speed position p₀. Feed: the mean deviation from p₀.</source>
        <translation>组：零速位置 p₀。进给率：相对 p₀ 的平均偏差。</translation>
    </message>
    <message>
        <source>Group: twice the standard deviation of the residuals of the line. Feed: the range (max − min) of its touches, the delay&apos;s stability.</source>
        <translation>组：直线残差标准差的两倍。进给率：该进给率各次触测的极差（最大 − 最小），即延迟的稳定性。</translation>
    </message>
    <message>
        <source>Touches</source>
        <translation>触测</translation>
    </message>
    <message>
        <source>Warnings</source>
        <translation>警告</translation>
    </message>
    <message>
        <source>No warnings.</source>
        <translation>无警告。</translation>
    </message>
    <message>
        <source>Delay to apply:</source>
        <translation>要应用的延迟：</translation>
    </message>
    <message>
        <source>Apply to scenario</source>
        <translation>应用到场景</translation>
    </message>
    <message>
        <source>Longest delay (safe side)</source>
        <translation>最长延迟（安全侧）</translation>
    </message>
    <message>
        <source>%1: τ = %2</source>
        <translation>%1：τ = %2</translation>
    </message>
    <message>
        <source>Import touches</source>
        <translation>导入触测</translation>
    </message>
    <message>
        <source>Fit the touches first.</source>
        <translation>请先拟合触测。</translation>
    </message>
    <message>
        <source>No scenario to apply the delay to.</source>
        <translation>没有可应用延迟的场景。</translation>
    </message>
    <message>
        <source>Controller latency = %1 delay %2 − interface %3 − half scan %4 = &lt;b&gt;%5&lt;/b&gt; (now %6)</source>
        <extracomment>%1 group, %2 its delay, %3 interface delay, %4 half scan period, %5 result, %6 now</extracomment>
        <translation>控制器延迟 = %1 延迟 %2 − 接口 %3 − 半个扫描周期 %4 = &lt;b&gt;%5&lt;/b&gt;（当前 %6）</translation>
    </message>
    <message>
        <source>Sets machine.controller_latency_s to the fitted delay less the probe&apos;s interface delay and half the scan period. With a latched input the fitted delay is the interface delay: it sets probe.interface_delay_s and leaves the latency alone.</source>
        <translation>将 machine.controller_latency_s 设为拟合延迟减去测头接口延迟和半个扫描周期。锁存输入时拟合延迟即接口延迟：设置 probe.interface_delay_s，控制器延迟保持不变。</translation>
    </message>
    <message>
        <source>Latched input: interface delay = %1 delay &lt;b&gt;%2&lt;/b&gt; (now %3); the controller latency is left as it is</source>
        <extracomment>%1 group, %2 its delay (the result), %3 the interface delay now</extracomment>
        <translation>锁存输入：接口延迟 = %1 延迟 &lt;b&gt;%2&lt;/b&gt;（当前 %3）；控制器延迟保持不变</translation>
    </message>
    <message>
        <source>Export CSV report…</source>
        <translation>导出 CSV 报告…</translation>
    </message>
    <message>
        <source>The delay per group, its stability per feed, every touch&apos;s residual and the warnings as CSV: the same file as probecycle-cli latency fit --report.</source>
        <translation>各组的延迟、各进给率下的延迟稳定性、每次触测的残差和警告，导出为 CSV：与 probecycle-cli latency fit --report 生成的文件相同。</translation>
    </message>
    <message>
        <source>Nothing to export: fit the touches first.</source>
        <translation>没有可导出的内容：请先拟合触测数据。</translation>
    </message>
    <message>
        <source>Export delay fit report</source>
        <translation>导出延迟拟合报告</translation>
    </message>
    <message>
        <source>The delay-stability test as a program for your control (LinuxCNC, grbl, Fanuc, Haas, Mitsubishi, Siemens), with the plan that the import of its log needs.</source>
        <translation>将延迟稳定性测试生成为适用于您的数控系统（LinuxCNC, grbl, Fanuc, Haas, Mitsubishi, Siemens）的程序，并附带导入其日志所需的计划。</translation>
    </message>
    <message>
        <source>What the control recorded while it ran the program, read with the program&apos;s plan into the touches and fitted.</source>
        <translation>数控系统运行程序时记录的内容，按程序的计划读入触测并拟合。</translation>
    </message>
</context>
<context>
    <name>probecycle::ui::Document</name>
    <message>
        <source>Untitled</source>
        <translation>未命名</translation>
    </message>
</context>
<context>
    <name>probecycle::ui::FitInput</name>
    <message>
        <source>Import CSV…</source>
        <translation>导入 CSV…</translation>
    </message>
    <message>
        <source>Fit</source>
        <translation>拟合</translation>
    </message>
    <message>
        <source>Program…</source>
        <translation>程序…</translation>
    </message>
    <message>
        <source>Import machine log…</source>
        <translation>导入数控日志…</translation>
    </message>
    <message>
        <source>CSV files (*.csv);;All files (*)</source>
        <translation>CSV 文件 (*.csv);;所有文件 (*)</translation>
    </message>
    <message>
        <source>The result shown is still that of the previous fit.</source>
        <translation>显示的仍是上一次拟合的结果。</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <source>Example data</source>
        <translation>示例数据</translation>
    </message>
    <message>
        <source>Touches simulated for the probe and machine of the scenario, with a known answer: to try the fit before measuring your own.</source>
        <translation>按场景中的测头和机床模拟的触测，答案已知：在测量您自己的数据之前先试用拟合。</translation>
    </message>
</context>
<context>
    <name>probecycle::ui::HelpGuide</name>
    <message>
        <source>One touch, phase by phase</source>
        <translation>一次触测的各个阶段</translation>
    </message>
    <message>
        <source>The formulas</source>
        <translation>公式</translation>
    </message>
    <message>
        <source>Reading the charts</source>
        <translation>如何看图表</translation>
    </message>
    <message>
        <source>&lt;b&gt;Cycle time against the probing feed&lt;/b&gt;: single-touch and two-touch (with the recommended backoff at each feed), the knee (the lowest feed whose cycle time is within the knee tolerance, 1 % by default, of the fastest valid cycle) and this cycle. Feeds whose cycle cannot run (overtravel over the limit, backoff too small) are invalid and never count as fast. &lt;b&gt;Overtravel and uncertainty&lt;/b&gt; against the feed, with the probe&apos;s limit and your target. &lt;b&gt;Phases&lt;/b&gt;: where the time goes. &lt;b&gt;Position and speed&lt;/b&gt; through the whole cycle.</source>
        <translation>&lt;b&gt;循环时间与探测进给率的关系&lt;/b&gt;：单次触测和两次触测（每个进给率都用推荐回退距离）、拐点（循环时间与最快有效循环相差不超过拐点容差（默认 1 %）的最低进给率）以及当前循环。循环无法执行的进给率（过行程超过极限、回退距离过小）无效，绝不会被当作更快。&lt;b&gt;过行程和不确定度&lt;/b&gt;与进给率的关系，以及测头极限和您的目标。&lt;b&gt;阶段&lt;/b&gt;：时间花在哪里。&lt;b&gt;位置和速度&lt;/b&gt;：整个循环的过程。</translation>
    </message>
    <message>
        <source>Warnings</source>
        <translation>警告</translation>
    </message>
    <message>
        <source>Errors come first: an error means the cycle cannot run as set, and no cycle time is shown for it. Where a warning has a one-click fix, its button sets the value that clears it; Undo takes it back.</source>
        <translation>错误排在最前：错误表示按当前设置循环无法执行，此时不显示循环时间。如果警告有一键修复，其按钮会设置消除该警告的数值；撤销可恢复原值。</translation>
    </message>
    <message>
        <source>Measuring the delay</source>
        <translation>如何测量延迟</translation>
    </message>
    <message>
        <source>On the machine, touch the same surface at several feeds (for example 30, 100, 300, 1000 and 2000 mm/min, five times each), each time from far enough out to be at full feed, and note the recorded positions. Paste them into the Latency tab (axis, direction, feed, measured) and press Fit: measured = p&lt;sub&gt;0&lt;/sub&gt; + v &amp;middot; &amp;tau;, and the delay &amp;tau; = t&lt;sub&gt;i&lt;/sub&gt; + t&lt;sub&gt;c&lt;/sub&gt; + t&lt;sub&gt;s&lt;/sub&gt;/2 gives the controller&apos;s latency t&lt;sub&gt;c&lt;/sub&gt;, which Apply writes into the scenario. The Calibration tab fits the stylus&apos;s runout and effective radius from a ring gauge touched at spindle 0&amp;deg; and 180&amp;deg;.</source>
        <translation>在机床上以多个进给率触测同一表面（例如 30、100、300、1000 和 2000 mm/min，各五次），每次都从足够远处开始以达到全速，并记下记录的位置。将它们粘贴到“延迟”选项卡（轴、方向、进给率、测量值），然后按“拟合”：测量值 = p&lt;sub&gt;0&lt;/sub&gt; + v &amp;middot; &amp;tau;，延迟 &amp;tau; = t&lt;sub&gt;i&lt;/sub&gt; + t&lt;sub&gt;c&lt;/sub&gt; + t&lt;sub&gt;s&lt;/sub&gt;/2 给出控制器延迟 t&lt;sub&gt;c&lt;/sub&gt;，“应用到场景”会把它写入场景。“标定”选项卡根据在主轴 0&amp;deg; 和 180&amp;deg; 触测的环规拟合测针的跳动和有效半径。</translation>
    </message>
    <message>
        <source>More</source>
        <translation>更多</translation>
    </message>
    <message>
        <source>ProbeCycle guide</source>
        <translation>ProbeCycle 指南</translation>
    </message>
    <message>
        <source>&lt;b&gt;Approach&lt;/b&gt;: from the start position to the surface at the probing feed. &lt;b&gt;Pretravel&lt;/b&gt;: the stylus deflects until the probe triggers. &lt;b&gt;Interface delay&lt;/b&gt; t&lt;sub&gt;i&lt;/sub&gt;: the probe&apos;s interface passes the signal on. &lt;b&gt;Controller delay&lt;/b&gt;: the control&apos;s latency t&lt;sub&gt;c&lt;/sub&gt; plus the wait until it scans the input, anything from nothing to a whole scan period t&lt;sub&gt;s&lt;/sub&gt;: the cycle time takes the mean wait, t&lt;sub&gt;s&lt;/sub&gt;/2, the overtravel the worst case, t&lt;sub&gt;s&lt;/sub&gt;. &lt;b&gt;Deceleration&lt;/b&gt;: the axis brakes to rest. Two-touch then &lt;b&gt;backs off&lt;/b&gt;, touches again slowly (the &lt;b&gt;2nd&lt;/b&gt; phases) and &lt;b&gt;returns&lt;/b&gt; to the start; a web, pocket, bore or boss adds the &lt;b&gt;positioning&lt;/b&gt; moves out from its centre to each touch and back. With a block change time, every move adds it (&lt;b&gt;block change&lt;/b&gt;).</source>
        <translation>&lt;b&gt;接近&lt;/b&gt;：以探测进给率从起始位置到表面。&lt;b&gt;预行程&lt;/b&gt;：测针偏转直到测头触发。&lt;b&gt;接口延迟&lt;/b&gt; t&lt;sub&gt;i&lt;/sub&gt;：测头接口传出信号。&lt;b&gt;控制器延迟&lt;/b&gt;：数控系统的延迟 t&lt;sub&gt;c&lt;/sub&gt;，加上等待系统扫描输入的时间，从零到一个完整的扫描周期 t&lt;sub&gt;s&lt;/sub&gt; 不等：循环时间取平均等待 t&lt;sub&gt;s&lt;/sub&gt;/2，过行程取最坏情况 t&lt;sub&gt;s&lt;/sub&gt;。&lt;b&gt;减速&lt;/b&gt;：轴制动到停止。两次触测随后&lt;b&gt;回退&lt;/b&gt;，再慢速触测一次（&lt;b&gt;第二次&lt;/b&gt;各阶段），然后&lt;b&gt;返回&lt;/b&gt;起始位置；凸台、槽、孔或圆柱还有从中心到每次触测处并返回的&lt;b&gt;定位&lt;/b&gt;移动。设置了程序段切换时间时，每次移动都加上这一时间（&lt;b&gt;程序段切换&lt;/b&gt;）。</translation>
    </message>
    <message>
        <source>Overtravel = pretravel + v &amp;middot; (t&lt;sub&gt;i&lt;/sub&gt; + t&lt;sub&gt;c&lt;/sub&gt; + t&lt;sub&gt;s&lt;/sub&gt;) + the braking distance (v&amp;middot;T/2 with a time constant T), the worst case; on average the axis stops v &amp;middot; t&lt;sub&gt;s&lt;/sub&gt;/2 short of it, and a two-touch cycle&apos;s second approach is the backoff less that mean stop. Scan range R = v &amp;middot; t&lt;sub&gt;s&lt;/sub&gt; (0 with a latched input). The trigger&apos;s uncertainty (k = 2) U&lt;sub&gt;t&lt;/sub&gt; = &amp;radic;(R&amp;sup2;/3 + repeatability&amp;sup2;), over &amp;radic;N for N repeats; the uncertainty (k = 2) is its budget with the terms no feed changes, U = &amp;radic;(U&lt;sub&gt;t&lt;/sub&gt;&amp;sup2; + 4 (lobing&amp;sup2;/3 + artefact&amp;sup2;/4 + machine repeatability&amp;sup2;/4 + thermal drift&amp;sup2;/3)). Recommended backoff = the first touch&apos;s overtravel + the larger of the reseat distance and the distance the second touch needs to reach its feed, rounded up to the micrometre. The tooltip of every parameter says where it enters.</source>
        <translation>过行程 = 预行程 + v &amp;middot; (t&lt;sub&gt;i&lt;/sub&gt; + t&lt;sub&gt;c&lt;/sub&gt; + t&lt;sub&gt;s&lt;/sub&gt;) + 制动距离（时间常数为 T 时为 v&amp;middot;T/2），这是最坏情况；平均而言，轴比它少走 v &amp;middot; t&lt;sub&gt;s&lt;/sub&gt;/2 就停止，两次触测的第二次接近等于回退距离减去这一平均停止距离。扫描范围 R = v &amp;middot; t&lt;sub&gt;s&lt;/sub&gt;（锁存输入时为 0）。触发不确定度（k = 2）U&lt;sub&gt;t&lt;/sub&gt; = &amp;radic;(R&amp;sup2;/3 + 重复性&amp;sup2;)，N 次重复时除以 &amp;radic;N；不确定度（k = 2）是它与不随进给率变化的各项组成的预算：U = &amp;radic;(U&lt;sub&gt;t&lt;/sub&gt;&amp;sup2; + 4 (各向异性&amp;sup2;/3 + 标准器&amp;sup2;/4 + 机床重复性&amp;sup2;/4 + 热漂移&amp;sup2;/3))。推荐回退距离 = 第一次触测的过行程 + 测头复位距离与第二次触测加速到其进给率所需距离中的较大者，向上取整到微米。每个参数的提示说明它在模型中的作用。</translation>
    </message>
    <message>
        <source>Getting started</source>
        <translation>入门</translation>
    </message>
    <message>
        <source>&lt;b&gt;1. Start near your machine.&lt;/b&gt; Choose the preset closest to your control and probe (Presets), or read a LinuxCNC machine from its INI file (File &amp;gt; Import Machine). Every value is typical until you replace it with yours. &lt;b&gt;2. Enter what you know.&lt;/b&gt; From the probe&apos;s data sheet: its pretravel, repeatability and overtravel limit; from the control: its scan period; from your cycle: the feature, the feeds and the backoff. What you do not know, the delays, you measure in the Latency tab (its Example data shows how). &lt;b&gt;3. Read the six numbers at the top.&lt;/b&gt; Cycle time: the whole cycle as set. Overtravel: how far the axis runs past the trigger, against the probe&apos;s limit, at the highest feed override. Trigger speed: the feed when the measuring touch triggers. Uncertainty (k = 2): the measurement&apos;s budget; its tooltip lists the terms. Recommended backoff: the least that lets the second touch reseat and reach its feed. Knee: the feed beyond which a faster search saves almost no time. &lt;b&gt;4. Follow the warnings&lt;/b&gt;, errors first; each button sets the value that clears its warning, and the Optimise tab finds the fastest settings that meet your limits. &lt;b&gt;Where the numbers come from&lt;/b&gt;: a model of the axis&apos;s motion (acceleration, filters, servo lag), the probe and the control&apos;s delays, with the formulas below; nothing is measured unless you measure it.</source>
        <translation>&lt;b&gt;1. 从接近您机床的设置开始。&lt;/b&gt;选择与您的数控系统和测头最接近的预设（预设菜单），或从 LinuxCNC 机床的 INI 文件读取机床（文件 &amp;gt; 导入机床）。在您替换为自己的值之前，所有数值都是典型值。&lt;b&gt;2. 输入您已知的数据。&lt;/b&gt;来自测头数据表：预行程、重复性和过行程极限；来自数控系统：扫描周期；来自您的循环：特征、进给率和回退距离。您不知道的延迟，可在“延迟”选项卡中测量（其“示例数据”演示了方法）。&lt;b&gt;3. 读懂顶部的六个数字。&lt;/b&gt;循环时间：按设置的整个循环。过行程：轴越过触发点的距离，与测头极限比较，按最高进给倍率计算。触发速度：测量触测触发时的进给率。不确定度（k = 2）：测量的不确定度预算，其提示列出各项。推荐回退距离：使第二次触测能够复位并达到其进给率的最小值。曲线拐点：超过该进给率后，更快的搜索几乎不再节省时间。&lt;b&gt;4. 按提示处理&lt;/b&gt;，先处理错误；每个按钮设置可消除该提示的值，“优化”选项卡可找到满足您限值的最快设置。&lt;b&gt;数字从何而来&lt;/b&gt;：来自轴运动（加速度、滤波器、伺服滞后）、测头和数控系统延迟的模型，公式见下文；除非您亲自测量，否则没有任何值是测量所得。</translation>
    </message>
    <message>
        <source>The README and the docs folder beside it explain the model in full, with its limits, the files, the command line and the lab. &lt;a href=&quot;%1&quot;&gt;Open the README&lt;/a&gt;.</source>
        <translation>README 及其旁边的 docs 文件夹完整说明了模型及其局限、文件、命令行和实验室功能。&lt;a href=&quot;%1&quot;&gt;打开 README&lt;/a&gt;。</translation>
    </message>
</context>
<context>
    <name>probecycle::ui::Lab</name>
    <message>
        <source>Points on one side</source>
        <translation>测点集中在一侧</translation>
    </message>
    <message>
        <source>Large stylus runout</source>
        <translation>测针跳动过大</translation>
    </message>
    <message>
        <source>Point off the circle</source>
        <translation>测点偏离圆</translation>
    </message>
    <message>
        <source>One orientation only: no runout</source>
        <translation>只有一个方向：无法求跳动</translation>
    </message>
    <message>
        <source>Three points: exact fit</source>
        <translation>三点：精确拟合</translation>
    </message>
    <message>
        <source>Length far from the nominal</source>
        <translation>长度与名义值相差过大</translation>
    </message>
    <message>
        <source>Fewer than 3 feeds</source>
        <translation>少于 3 个进给率</translation>
    </message>
    <message>
        <source>Unstable delay</source>
        <translation>延迟不稳定</translation>
    </message>
    <message>
        <source>Residuals curve: the delay changes</source>
        <translation>残差呈曲线：延迟在变化</translation>
    </message>
    <message>
        <source>Negative delay</source>
        <translation>负延迟</translation>
    </message>
    <message>
        <source>One touch at a feed</source>
        <translation>某进给率只有一次触测</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <extracomment>%1 the group (&quot;X+&quot;), %2 the warning&apos;s title</extracomment>
        <translation>%1：%2</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>CSV 文件 (*.csv)</translation>
    </message>
    <message>
        <source>%1 could not be written: %2</source>
        <translation>无法写入 %1：%2</translation>
    </message>
</context>
<context>
    <name>probecycle::ui::MachineLogDialog</name>
    <message>
        <source>delay-stability test</source>
        <translation>延迟稳定性测试</translation>
    </message>
    <message>
        <source>ring-gauge calibration</source>
        <translation>环规标定</translation>
    </message>
    <message>
        <source>tuned cycle</source>
        <translation>优化后的循环</translation>
    </message>
    <message>
        <source>%1 is not a probing plan:
%2</source>
        <extracomment>%1 the plan file, %2 what is wrong in it (one problem a line)</extracomment>
        <translation>%1 不是测量计划：
%2</translation>
    </message>
    <message>
        <source>%1 is the plan of a %2 program; this tab reads the log of a %3 program.</source>
        <extracomment>%1 the plan file, %2 its program (&quot;ring-gauge calibration&quot;), %3 this tab&apos;s</extracomment>
        <translation>%1 是“%2”程序的计划；此选项卡读取“%3”程序的日志。</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <extracomment>%1 the machine log&apos;s file, %2 the problem with its line</extracomment>
        <translation>%1：%2</translation>
    </message>
    <message>
        <source>Import machine log</source>
        <translation>导入数控日志</translation>
    </message>
    <message>
        <source>What the control recorded while it ran a %1 program of ProbeCycle&apos;s, with the plan saved beside the program. The positions fill the paste box and are fitted; on any problem nothing changes.</source>
        <extracomment>%1 the program (&quot;delay-stability test&quot;)</extracomment>
        <translation>数控系统运行 ProbeCycle 的“%1”程序时记录的内容，以及与程序一同保存的计划。位置填入粘贴框并进行拟合；出现任何问题时不作任何更改。</translation>
    </message>
    <message>
        <source>Control</source>
        <translation>数控系统</translation>
    </message>
    <message>
        <source>The log the program writes: probecycle_log.txt in LinuxCNC&apos;s working directory.</source>
        <translation>程序写出的日志：LinuxCNC 工作目录中的 probecycle_log.txt。</translation>
    </message>
    <message>
        <source>The sender&apos;s console saved to a file: grbl answers [PRB:x,y,z:1] after each probe (set $13=0 for mm).</source>
        <translation>发送软件的控制台保存为文件：grbl 在每次触测后回复 [PRB:x,y,z:1]（设置 $13=0 以使用 mm）。</translation>
    </message>
    <message>
        <source>Plan</source>
        <translation>计划</translation>
    </message>
    <message>
        <source>NAME.plan.json, saved with the program</source>
        <translation>名称.plan.json，与程序一同保存</translation>
    </message>
    <message>
        <source>Browse…</source>
        <translation>浏览…</translation>
    </message>
    <message>
        <source>Log</source>
        <translation>日志</translation>
    </message>
    <message>
        <source>Import</source>
        <translation>导入</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <source>Choose the plan</source>
        <translation>选择计划</translation>
    </message>
    <message>
        <source>Probing plans (*.plan.json *.json);;All files (*)</source>
        <translation>测量计划 (*.plan.json *.json);;所有文件 (*)</translation>
    </message>
    <message>
        <source>Choose the machine log</source>
        <translation>选择数控日志</translation>
    </message>
    <message>
        <source>Logs (*.txt *.log);;All files (*)</source>
        <translation>日志 (*.txt *.log);;所有文件 (*)</translation>
    </message>
    <message>
        <source>The program&apos;s DPRNT output as the control sent it (a serial terminal, a memory card or a file): the lines from PROBECYCLE PLAN on.</source>
        <translation>控制系统发出的程序 DPRNT 输出（串口终端、存储卡或文件）：从 PROBECYCLE PLAN 开始的各行。</translation>
    </message>
    <message>
        <source>The common variables #500 to #999 after the program ended, as the control outputs them or copied from its variable screen: one line &quot;#n value&quot; each.</source>
        <translation>程序结束后的公共变量 #500 至 #999，由控制系统输出或从其变量画面抄录：每行一个“#n 值”。</translation>
    </message>
    <message>
        <source>The file PROBECYCLE_LOG that the program&apos;s WRITE appends to, copied from the control: its last run is read.</source>
        <translation>程序的 WRITE 追加写入的文件 PROBECYCLE_LOG，从控制系统复制而来：读取其中最后一次运行。</translation>
    </message>
</context>
<context>
    <name>probecycle::ui::MainWindow</name>
    <message>
        <source>About ProbeCycle</source>
        <translation>关于 ProbeCycle</translation>
    </message>
    <message>
        <source>&lt;p&gt;&lt;b&gt;ProbeCycle&lt;/b&gt; %1&lt;/p&gt;&lt;p&gt;Cycle time, overtravel and uncertainty of touch-trigger probing cycles on CNC machine tools.&lt;/p&gt;&lt;p&gt;Every value in the model is a typical one until you replace it with your measured value.&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;ProbeCycle&lt;/b&gt; %1&lt;/p&gt;&lt;p&gt;数控机床触发式测头测量循环的循环时间、过行程和不确定度。&lt;/p&gt;&lt;p&gt;在您用实测值替换之前，模型中的每个值都只是典型值。&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&amp;New</source>
        <translation>新建(&amp;N)</translation>
    </message>
    <message>
        <source>Start from the default scenario (typical values)</source>
        <translation>从默认场景开始（典型值）</translation>
    </message>
    <message>
        <source>&amp;Open…</source>
        <translation>打开(&amp;O)…</translation>
    </message>
    <message>
        <source>Open a scenario file (the JSON the command-line tool reads)</source>
        <translation>打开场景文件（命令行工具读取的 JSON）</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>保存(&amp;S)</translation>
    </message>
    <message>
        <source>Save the scenario as JSON</source>
        <translation>将场景保存为 JSON</translation>
    </message>
    <message>
        <source>Save &amp;As…</source>
        <translation>另存为(&amp;A)…</translation>
    </message>
    <message>
        <source>Export CSV &amp;Report…</source>
        <translation>导出 CSV 报告(&amp;R)…</translation>
    </message>
    <message>
        <source>Scenario, summary, phases, warnings and a feed sweep as CSV, the same as the command-line tool writes</source>
        <translation>以 CSV 格式导出场景、摘要、各阶段、警告和进给率扫描，与命令行工具输出的相同</translation>
    </message>
    <message>
        <source>Export Charts as &amp;PNG…</source>
        <translation>将图表导出为 PNG(&amp;P)…</translation>
    </message>
    <message>
        <source>Save the four charts as one PNG image</source>
        <translation>将四个图表保存为一张 PNG 图片</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>退出(&amp;Q)</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>撤销(&amp;U)</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>重做(&amp;R)</translation>
    </message>
    <message>
        <source>Undo</source>
        <translation>撤销</translation>
    </message>
    <message>
        <source>&amp;Pin Baseline</source>
        <translation>固定基准(&amp;P)</translation>
    </message>
    <message>
        <source>Keep the current scenario as a baseline: its curves stay drawn dashed and the readouts show the difference</source>
        <translation>将当前场景固定为基准：其曲线以虚线保留，读数显示差值</translation>
    </message>
    <message>
        <source>&amp;Clear Baseline</source>
        <translation>清除基准(&amp;C)</translation>
    </message>
    <message>
        <source>&amp;About ProbeCycle</source>
        <translation>关于 ProbeCycle(&amp;A)</translation>
    </message>
    <message>
        <source>Presets hold typical values: replace them with measured ones</source>
        <translation>预设为典型值：请替换为实测值</translation>
    </message>
    <message>
        <source>System language</source>
        <translation>系统语言</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>文件(&amp;F)</translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation>最近打开(&amp;R)</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>编辑(&amp;E)</translation>
    </message>
    <message>
        <source>&amp;Presets</source>
        <translation>预设(&amp;P)</translation>
    </message>
    <message>
        <source>P&amp;robe class</source>
        <translation>测头类型(&amp;R)</translation>
    </message>
    <message>
        <source>&amp;Compare</source>
        <translation>比较(&amp;C)</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>视图(&amp;V)</translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation>语言(&amp;L)</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>帮助(&amp;H)</translation>
    </message>
    <message>
        <source>Warnings</source>
        <translation>警告</translation>
    </message>
    <message>
        <source>Main toolbar</source>
        <translation>主工具栏</translation>
    </message>
    <message>
        <source>Unsaved changes</source>
        <translation>未保存的更改</translation>
    </message>
    <message>
        <source>Save the changes to %1?</source>
        <translation>是否保存对 %1 的更改？</translation>
    </message>
    <message>
        <source>change %1</source>
        <translation>更改%1</translation>
    </message>
    <message>
        <source>Default scenario: typical values, to be replaced with measured ones</source>
        <translation>默认场景：典型值，请替换为实测值</translation>
    </message>
    <message>
        <source>Could not open the scenario</source>
        <translation>无法打开场景</translation>
    </message>
    <message>
        <source>%1 could not be read: %2</source>
        <translation>无法读取 %1：%2</translation>
    </message>
    <message>
        <source>%1 is not a valid scenario:
%2</source>
        <translation>%1 不是有效的场景：
%2</translation>
    </message>
    <message>
        <source>Opened %1</source>
        <translation>已打开 %1</translation>
    </message>
    <message>
        <source>Could not save the scenario</source>
        <translation>无法保存场景</translation>
    </message>
    <message>
        <source>%1 could not be written: %2</source>
        <translation>无法写入 %1：%2</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>已保存 %1</translation>
    </message>
    <message>
        <source>Could not export the report</source>
        <translation>无法导出报告</translation>
    </message>
    <message>
        <source>The scenario is not valid; see the warnings panel.</source>
        <translation>场景无效，请查看警告面板。</translation>
    </message>
    <message>
        <source>Report written to %1</source>
        <translation>报告已写入 %1</translation>
    </message>
    <message>
        <source>Could not export the charts</source>
        <translation>无法导出图表</translation>
    </message>
    <message>
        <source>Charts written to %1</source>
        <translation>图表已写入 %1</translation>
    </message>
    <message>
        <source>Could not apply the preset</source>
        <translation>无法应用预设</translation>
    </message>
    <message>
        <source>preset %1</source>
        <translation>预设 %1</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>（无）</translation>
    </message>
    <message>
        <source>Export CSV report</source>
        <translation>导出 CSV 报告</translation>
    </message>
    <message>
        <source>CSV (*.csv)</source>
        <translation>CSV (*.csv)</translation>
    </message>
    <message>
        <source>Export charts as PNG</source>
        <translation>将图表导出为 PNG</translation>
    </message>
    <message>
        <source>PNG image (*.png)</source>
        <translation>PNG 图片 (*.png)</translation>
    </message>
    <message>
        <source>Baseline pinned: change parameters to compare against it</source>
        <translation>已固定基准：更改参数即可与之比较</translation>
    </message>
    <message>
        <source>set backoff to recommended</source>
        <translation>将回退距离设为推荐值</translation>
    </message>
    <message>
        <source>drop feed to the knee</source>
        <translation>将进给率降至拐点</translation>
    </message>
    <message>
        <source>start far enough out to reach the feed</source>
        <translation>起点足够远以达到进给率</translation>
    </message>
    <message>
        <source>&amp;Undo %1</source>
        <translation>撤销 %1(&amp;U)</translation>
    </message>
    <message>
        <source>&amp;Redo %1</source>
        <translation>重做 %1(&amp;R)</translation>
    </message>
    <message>
        <source>Redo</source>
        <translation>重做</translation>
    </message>
    <message>
        <source>apply the measured delay</source>
        <translation>应用测得的延迟</translation>
    </message>
    <message>
        <source>Cycle</source>
        <translation>循环</translation>
    </message>
    <message>
        <source>Calibration</source>
        <translation>标定</translation>
    </message>
    <message>
        <source>Latency</source>
        <translation>延迟</translation>
    </message>
    <message>
        <source>the image could not be encoded as PNG</source>
        <translation>无法将图像编码为 PNG</translation>
    </message>
    <message>
        <source>Comparison</source>
        <translation>比较测量</translation>
    </message>
    <message>
        <source>&amp;Machine (skip input, control)</source>
        <translation>机床（跳跃输入、控制系统）(&amp;M)</translation>
    </message>
    <message>
        <source>Cycle (%1)</source>
        <translation>循环（%1）</translation>
    </message>
    <message>
        <source>drop feed for the overtravel</source>
        <translation>为过行程降低进给率</translation>
    </message>
    <message>
        <source>Errors: %1</source>
        <translation>错误：%1</translation>
    </message>
    <message>
        <source>Warnings: %1</source>
        <translation>警告：%1</translation>
    </message>
    <message>
        <source>Notes: %1</source>
        <translation>提示：%1</translation>
    </message>
    <message>
        <source>on</source>
        <translation>开</translation>
    </message>
    <message>
        <source>off</source>
        <translation>关</translation>
    </message>
    <message>
        <source>%1: nothing to change, the values are already the preset&apos;s</source>
        <translation>%1：无需更改，数值已与预设相同</translation>
    </message>
    <message>
        <source>%1: typical values applied (Undo restores): %2</source>
        <translation>%1：已应用典型值（撤销可恢复原值）：%2</translation>
    </message>
    <message>
        <source>%1 - %2 - %3 - ProbeCycle %4</source>
        <translation>%1 — %2 — %3 — ProbeCycle %4</translation>
    </message>
    <message>
        <source>&amp;Guide</source>
        <translation>指南(&amp;G)</translation>
    </message>
    <message>
        <source>The project you open replaces the lab&apos;s data (touches, fits, comparison settings), which is in no project file yet. Save everything as a project first?</source>
        <translation>要打开的项目将替换实验室数据（触测点、拟合、比对设置），这些数据尚未保存在任何项目文件中。先将全部内容另存为项目吗？</translation>
    </message>
    <message>
        <source>Could not open the project</source>
        <translation>无法打开项目</translation>
    </message>
    <message>
        <source>%1 is not a valid project:
%2</source>
        <translation>%1 不是有效的项目：
%2</translation>
    </message>
    <message>
        <source>Could not save the project</source>
        <translation>无法保存项目</translation>
    </message>
    <message>
        <source>Open scenario or project</source>
        <translation>打开场景或项目</translation>
    </message>
    <message>
        <source>Scenarios and projects (*.json *.probecycle);;Project (*.probecycle);;Scenario (*.json);;All files (*)</source>
        <translation>场景和项目 (*.json *.probecycle);;项目 (*.probecycle);;场景 (*.json);;所有文件 (*)</translation>
    </message>
    <message>
        <source>ProbeCycle project: scenario, lab and comparison (*.probecycle)</source>
        <translation>ProbeCycle 项目：场景、实验室和比对 (*.probecycle)</translation>
    </message>
    <message>
        <source>Scenario only (*.json)</source>
        <translation>仅场景 (*.json)</translation>
    </message>
    <message>
        <source>Save as</source>
        <translation>另存为</translation>
    </message>
    <message>
        <source>Export P&amp;DF Report…</source>
        <translation>导出 PDF 报告(&amp;D)…</translation>
    </message>
    <message>
        <source>A4 pages to hand over: the current tab&apos;s results, charts, warnings with their fixes and the inputs, in the interface&apos;s language</source>
        <translation>可交付的 A4 页面：当前选项卡的结果、图表、警告及其修正和输入参数，使用界面语言</translation>
    </message>
    <message>
        <source>Export PDF report</source>
        <translation>导出 PDF 报告</translation>
    </message>
    <message>
        <source>PDF (*.pdf)</source>
        <translation>PDF (*.pdf)</translation>
    </message>
    <message>
        <source>yes</source>
        <translation>是</translation>
    </message>
    <message>
        <source>no</source>
        <translation>否</translation>
    </message>
    <message>
        <source>ProbeCycle report: %1</source>
        <translation>ProbeCycle 报告：%1</translation>
    </message>
    <message>
        <source>Figures computed by ProbeCycle %1 from a model of the machine, probe and cycle with the inputs listed in this report. They are estimates for setting up the cycle, not a calibration certificate.</source>
        <translation>数值由 ProbeCycle %1 根据机床、测头和循环的模型及本报告所列输入计算得出。它们是用于设置循环的估计值，而非校准证书。</translation>
    </message>
    <message>
        <source>%1 · %2 · ProbeCycle %3</source>
        <translation>%1 · %2 · ProbeCycle %3</translation>
    </message>
    <message>
        <source>No results yet: %1</source>
        <translation>尚无结果：%1</translation>
    </message>
    <message>
        <source>Results</source>
        <translation>计算结果</translation>
    </message>
    <message>
        <source>Quantity</source>
        <translation>量</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>数值</translation>
    </message>
    <message>
        <source>Detail</source>
        <translation>详情</translation>
    </message>
    <message>
        <source>Warnings and what to change</source>
        <translation>警告及应做的更改</translation>
    </message>
    <message>
        <source>No warnings: the cycle runs as set.</source>
        <translation>无警告：循环按设置运行。</translation>
    </message>
    <message>
        <source>The scenario</source>
        <translation>场景</translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation>参数</translation>
    </message>
    <message>
        <source>Key</source>
        <translation>键</translation>
    </message>
    <message>
        <source>Could not export the PDF report</source>
        <translation>无法导出 PDF 报告</translation>
    </message>
    <message>
        <source>PDF report written to %1</source>
        <translation>PDF 报告已写入 %1</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <extracomment>%1 the severity (Error, Warning, Note), %2 the warning&apos;s title</extracomment>
        <translation>%1：%2</translation>
    </message>
    <message>
        <source>apply the best settings</source>
        <translation>应用最佳设置</translation>
    </message>
    <message>
        <source>Optimise</source>
        <translation>优化</translation>
    </message>
    <message>
        <source>The optimiser&apos;s recommendation</source>
        <translation>优化器的建议</translation>
    </message>
    <message>
        <source>The scenario is not valid; see the warnings.</source>
        <translation>场景无效；请查看警告。</translation>
    </message>
    <message>
        <source>Program for the &amp;Control…</source>
        <translation>生成数控程序(&amp;C)…</translation>
    </message>
    <message>
        <source>The cycle as a probing program for your control (LinuxCNC, grbl, Fanuc, Haas, Mitsubishi, Siemens), with the values set here</source>
        <translation>将此循环生成为适用于您的数控系统（LinuxCNC, grbl, Fanuc, Haas, Mitsubishi, Siemens）的测量程序，使用此处设定的值</translation>
    </message>
    <message>
        <source>&amp;LinuxCNC INI…</source>
        <translation>LinuxCNC INI(&amp;L)…</translation>
    </message>
    <message>
        <source>The machine from a LinuxCNC 2.9 configuration: the axes&apos; acceleration and speed limits and the servo period, as ProbeCycle&apos;s LinuxCNC programs (exact stop) meet them. The drives&apos; lag is not in the file and is set to none.</source>
        <translation>从 LinuxCNC 2.9 配置读取机床：各轴的加速度和速度限制以及伺服周期，按 ProbeCycle 的 LinuxCNC 程序（准停）所受的作用取值。驱动的滞后不在该文件中，设为无。</translation>
    </message>
    <message>
        <source>&amp;Import Machine</source>
        <translation>导入机床(&amp;I)</translation>
    </message>
    <message>
        <source>Could not import the machine</source>
        <translation>无法导入机床</translation>
    </message>
    <message>
        <source>%1 is not a valid LinuxCNC configuration:
%2</source>
        <translation>%1 不是有效的 LinuxCNC 配置：
%2</translation>
    </message>
    <message>
        <source>import the machine from %1</source>
        <translation>从 %1 导入机床</translation>
    </message>
    <message>
        <source>%1: nothing to change, the machine is already this one</source>
        <translation>%1：无需更改，机床已与之相同</translation>
    </message>
    <message>
        <source>%1: machine imported (Undo restores): %2</source>
        <translation>%1：已导入机床（撤销可恢复原值）：%2</translation>
    </message>
    <message>
        <source>Import the machine from a LinuxCNC INI file</source>
        <translation>从 LinuxCNC INI 文件导入机床</translation>
    </message>
    <message>
        <source>LinuxCNC configuration (*.ini *.expanded);;All files (*)</source>
        <translation>LinuxCNC 配置 (*.ini *.expanded);;所有文件 (*)</translation>
    </message>
    <message>
        <source>search past the touch&apos;s stop</source>
        <translation>搜索超过触测停止位置</translation>
    </message>
    <message>
        <source>drop the positioning feed for the overtravel</source>
        <translation>为过行程降低定位进给率</translation>
    </message>
    <message>
        <source>Uncertainty budget</source>
        <translation>不确定度预算</translation>
    </message>
    <message>
        <source>%1 points: the tables give their statistics and the %2 that deviate most. The CSV report (Export report…) has every point.</source>
        <translation>%1 个点：表格给出其统计值及偏差最大的 %2 个点。CSV 报告（导出报告…）包含全部点。</translation>
    </message>
    <message>
        <source>There is no preset %1.</source>
        <translation>没有预设 %1。</translation>
    </message>
    <message>
        <source>Report De&amp;tails…</source>
        <translation>报告信息(&amp;T)…</translation>
    </message>
    <message>
        <source>Customer, machine, part, author and notes for the top of the PDF report</source>
        <translation>PDF 报告开头的客户、机床、零件、作者和备注</translation>
    </message>
    <message>
        <source>Charts</source>
        <translation>图表</translation>
    </message>
    <message>
        <source>Suggested change: %1</source>
        <translation>建议的更改：%1</translation>
    </message>
</context>
<context>
    <name>probecycle::ui::OptimisePanel</name>
    <message>
        <source>The current settings do not meet the requirements; the fastest that do take %1 a cycle.</source>
        <translation>当前设置不满足要求；满足要求的最快设置每个循环需 %1。</translation>
    </message>
    <message>
        <source>The current settings are already the fastest that meet the requirements.</source>
        <translation>当前设置已是满足要求的最快设置。</translation>
    </message>
    <message>
        <source>The best settings save %1 a cycle: %2 instead of %3 (%4 % less).</source>
        <translation>最佳设置每个循环节省 %1：%2，而非 %3（减少 %4 %）。</translation>
    </message>
    <message>
        <source>a cycle that can run (the backoff and the probe&apos;s overtravel limit)</source>
        <translation>可运行的循环（回退距离和测头过行程极限）</translation>
    </message>
    <message>
        <source>the target uncertainty, %1</source>
        <translation>目标不确定度 %1</translation>
    </message>
    <message>
        <source>the current uncertainty, %1 (no target is set)</source>
        <translation>当前不确定度 %1（未设目标）</translation>
    </message>
    <message>
        <source>the overtravel allowed, %1 % of the probe&apos;s limit</source>
        <translation>允许的过行程，测头极限的 %1 %</translation>
    </message>
    <message>
        <source>the probe&apos;s maximum feed, %1</source>
        <translation>测头最大进给率 %1</translation>
    </message>
    <message>
        <source>the machine&apos;s rapid feed, %1</source>
        <translation>机床快速进给率 %1</translation>
    </message>
    <message>
        <source>at most %1 measurements</source>
        <translation>最多 %1 次测量</translation>
    </message>
    <message>
        <source>What limits it: %1.</source>
        <translation>限制因素：%1。</translation>
    </message>
    <message>
        <source>Saved per part: %1; per year: %2 h of machine time</source>
        <translation>每件节省：%1；每年：%2 小时机床时间</translation>
    </message>
    <message>
        <source>, worth %1 at the machine rate</source>
        <translation>，按机床小时费率计价值 %1</translation>
    </message>
    <message>
        <source>What else would save time:</source>
        <translation>还有哪些可以节省时间：</translation>
    </message>
    <message>
        <source>Requirements</source>
        <translation>要求</translation>
    </message>
    <message>
        <source>Overtravel allowed, of the probe&apos;s limit</source>
        <translation>允许的过行程（占测头极限）</translation>
    </message>
    <message>
        <source>The optimiser keeps the overtravel at or under this share of the probe&apos;s overtravel limit (80 %: where the cycle starts to warn).</source>
        <translation>优化器使过行程不超过测头过行程极限的这一比例（80 %：循环开始警告的位置）。</translation>
    </message>
    <message>
        <source>Current</source>
        <translation>当前</translation>
    </message>
    <message>
        <source>Best</source>
        <translation>最佳</translation>
    </message>
    <message>
        <source>Strategy</source>
        <translation>策略</translation>
    </message>
    <message>
        <source>Probing feedrate</source>
        <translation>探测进给率</translation>
    </message>
    <message>
        <source>Measuring feedrate</source>
        <translation>测量进给率</translation>
    </message>
    <message>
        <source>Backoff</source>
        <translation>回退距离</translation>
    </message>
    <message>
        <source>Measurements</source>
        <translation>测量次数</translation>
    </message>
    <message>
        <source>Cycle time</source>
        <translation>循环时间</translation>
    </message>
    <message>
        <source>Uncertainty (k = 2)</source>
        <translation>不确定度 (k = 2)</translation>
    </message>
    <message>
        <source>Overtravel</source>
        <translation>过行程</translation>
    </message>
    <message>
        <source>Apply the best settings</source>
        <translation>应用最佳设置</translation>
    </message>
    <message>
        <source>Sets strategy, feeds, backoff, start distance and measurements to the best ones, as one step that Undo takes back</source>
        <translation>将策略、进给率、回退距离、起始距离和测量次数设为最佳值，作为一步，可用撤销恢复</translation>
    </message>
    <message>
        <source>Fastest cycle at each uncertainty</source>
        <translation>各不确定度下的最快循环</translation>
    </message>
    <message>
        <source>Uncertainty, k = 2 [µm]</source>
        <translation>不确定度，k = 2 [µm]</translation>
    </message>
    <message>
        <source>Cycle time [s]</source>
        <translation>循环时间 [s]</translation>
    </message>
    <message>
        <source>Fastest valid settings</source>
        <translation>最快的有效设置</translation>
    </message>
    <message>
        <source>Approach distance</source>
        <translation>接近距离</translation>
    </message>
    <message>
        <source>Positioning feed</source>
        <translation>定位进给率</translation>
    </message>
    <message>
        <source>Target uncertainty</source>
        <translation>目标不确定度</translation>
    </message>
    <message>
        <source>Current uncertainty</source>
        <translation>当前不确定度</translation>
    </message>
    <message>
        <source>the start distance: at least %1, and the part&apos;s position uncertainty plus the distance to reach the probing feed</source>
        <translation>起始距离：至少 %1，且为零件位置不确定度加上达到探测进给率所需的距离</translation>
    </message>
    <message>
        <source>the slowest feed allowed, %1</source>
        <translation>允许的最低进给率，%1</translation>
    </message>
    <message>
        <source>Overtravel at %1 %</source>
        <translation>%1 % 时的过行程</translation>
    </message>
</context>
<context>
    <name>probecycle::ui::ParameterPanel</name>
    <message>
        <source>Typical values: replace them with your measured ones.</source>
        <translation>典型值：请替换为您的实测值。</translation>
    </message>
    <message>
        <source>The defaults and the presets are typical values for a machining centre and its probe. Replace them with the ones measured on your machine.</source>
        <translation>默认值和预设是加工中心及其测头的典型值。请替换为在您机床上测得的值。</translation>
    </message>
</context>
<context>
    <name>probecycle::ui::PasteBox</name>
    <message>
        <source>%1 could not be read: %2</source>
        <translation>无法读取 %1：%2</translation>
    </message>
</context>
<context>
    <name>probecycle::ui::ProgramDialog</name>
    <message>
        <source>Ring-gauge calibration program</source>
        <translation>环规标定程序</translation>
    </message>
    <message>
        <source>From the gauge centre: X+, X−, Y+, Y− with the spindle at 0°, a pause to turn it to 180°, the same four, each point with the scenario&apos;s strategy and feeds. Every move is incremental from where the probe stands. Save the plan with the program: &quot;Import machine log…&quot; needs it.</source>
        <translation>从环规中心出发：主轴在 0° 时触测 X+、X−、Y+、Y−，暂停以将主轴转到 180°，再触测同样四点；每个点采用场景的策略和进给率。所有移动均为从测头当前位置起的增量移动。请将计划与程序一同保存：“导入数控日志…”需要它。</translation>
    </message>
    <message>
        <source>Gauge diameter</source>
        <translation>环规直径</translation>
    </message>
    <message>
        <source>The calibrated diameter of the ring gauge, from its certificate.</source>
        <translation>环规的校准直径，取自其证书。</translation>
    </message>
    <message>
        <source>Ball diameter</source>
        <translation>测球直径</translation>
    </message>
    <message>
        <source>The stylus ball&apos;s diameter: the room to the wall is the gauge&apos;s radius less the ball&apos;s.</source>
        <translation>测针测球的直径：到侧壁的距离为环规半径减去测球半径。</translation>
    </message>
    <message>
        <source>Centre tolerance</source>
        <translation>中心容差</translation>
    </message>
    <message>
        <source>How far off the gauge centre the probe may start: each first touch searches this much further.</source>
        <translation>测头起始位置可偏离环规中心的距离：每次第一次触测都会多搜索这么远。</translation>
    </message>
    <message>
        <source>Delay-stability test program</source>
        <translation>延迟稳定性测试程序</translation>
    </message>
    <message>
        <source>Along one axis and direction: a locating touch, then the repeats at each feed, each from far enough out to touch at full speed, with a rapid retract between touches. Every move is incremental from where the probe stands. Save the plan with the program: &quot;Import machine log…&quot; needs it.</source>
        <translation>沿一个轴和方向：先一次定位触测，然后在每个进给率下重复触测，每次都从足够远处开始以便全速触测，触测之间快速退回。所有移动均为从测头当前位置起的增量移动。请将计划与程序一同保存：“导入数控日志…”需要它。</translation>
    </message>
    <message>
        <source>Axis and direction</source>
        <translation>轴和方向</translation>
    </message>
    <message>
        <source>The direction of travel of the touches. One per program: the control cannot jog to another surface at a pause; paste the imports of several programs together.</source>
        <translation>触测的行程方向。每个程序一个：数控系统在暂停时无法点动到另一个表面；请将多个程序的导入结果粘贴在一起。</translation>
    </message>
    <message>
        <source>Feeds</source>
        <translation>进给率列表</translation>
    </message>
    <message>
        <source>The feeds of the touches, %1, separated by semicolons or spaces; at least two.</source>
        <translation>触测的进给率，%1，用分号或空格分隔；至少两个。</translation>
    </message>
    <message>
        <source>Touches per feed</source>
        <translation>每个进给率的触测次数</translation>
    </message>
    <message>
        <source>Start margin</source>
        <translation>起点余量</translation>
    </message>
    <message>
        <source>Each touch starts this much farther out than the distance the axis needs to reach its feed.</source>
        <translation>每次触测的起点比轴达到其进给率所需的距离再远这么多。</translation>
    </message>
    <message>
        <source>Start at most</source>
        <translation>起点最远距离</translation>
    </message>
    <message>
        <source>The probe stands at most this far from the surface when the program starts; the locating touch searches this far.</source>
        <translation>程序开始时测头距表面最多这么远；定位触测搜索这么远。</translation>
    </message>
    <message>
        <source>Control</source>
        <translation>数控系统</translation>
    </message>
    <message>
        <source>The control&apos;s G-code dialect.</source>
        <translation>数控系统的 G 代码方言。</translation>
    </message>
    <message>
        <source>Program</source>
        <translation>程序</translation>
    </message>
    <message>
        <source>Save program…</source>
        <translation>保存程序…</translation>
    </message>
    <message>
        <source>Writes the program and, beside it, its plan (NAME.plan.json), which the import of the machine&apos;s log needs.</source>
        <translation>写出程序，并在其旁边写出其计划（名称.plan.json），导入数控日志时需要它。</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>关闭</translation>
    </message>
    <message>
        <source>%1: “%2” are not numbers separated by semicolons or spaces</source>
        <extracomment>%1 the label of the feeds box, %2 what it holds</extracomment>
        <translation>%1：“%2”不是用分号或空格分隔的数字</translation>
    </message>
    <message>
        <source>%1 could not be written: %2</source>
        <translation>无法写入 %1：%2</translation>
    </message>
    <message>
        <source>Saved %1 and its plan %2</source>
        <extracomment>%1 the program&apos;s file, %2 its plan&apos;s</extracomment>
        <translation>已保存 %1 及其计划 %2</translation>
    </message>
    <message>
        <source>%1 programs (*.%2);;All files (*)</source>
        <extracomment>%1 the control (&quot;LinuxCNC&quot;), %2 the program&apos;s extension (&quot;ngc&quot;)</extracomment>
        <translation>%1 程序 (*.%2);;所有文件 (*)</translation>
    </message>
    <message>
        <source>Save program</source>
        <translation>保存程序</translation>
    </message>
    <message>
        <source>No program: the options are refused (see the message).</source>
        <translation>没有程序：选项被拒绝（见提示信息）。</translation>
    </message>
    <message>
        <source>Spindle to 180°</source>
        <translation>主轴转到 180°</translation>
    </message>
    <message>
        <source>your control&apos;s block, from its manual</source>
        <translation>您的系统的程序段，见其手册</translation>
    </message>
    <message>
        <source>The block your control turns the spindle to 180° with. The Fanuc-type programs need it: M19 with an angle differs by maker and machine, and ProbeCycle does not guess it (the CLI&apos;s --orient-180).</source>
        <translation>您的数控系统将主轴转到 180° 所用的程序段。Fanuc 类程序需要它：带角度的 M19 因厂商和机床而异，ProbeCycle 不会猜测（CLI 中为 --orient-180）。</translation>
    </message>
    <message>
        <source>Tuned cycle program</source>
        <translation>调优循环程序</translation>
    </message>
    <message>
        <source>The direction of travel of the touch.</source>
        <translation>触测的行程方向。</translation>
    </message>
    <message>
        <source>The axis the two walls are touched along, X or Y (both directions, + first).</source>
        <translation>沿其触测两侧的轴，X 或 Y（两个方向，先 +）。</translation>
    </message>
    <message>
        <source>Not used: a bore or boss is touched at X+, X-, Y+ and Y-.</source>
        <translation>不使用：孔或圆柱在 X+、X-、Y+ 和 Y- 处触测。</translation>
    </message>
    <message>
        <source>The scenario&apos;s cycle on a surface, as plain probing moves: its strategy, feeds, backoff and start distance, the values you tuned here, not a maker&apos;s cycle call. The probe stands at the start distance in front of the surface. Every move is incremental from where the probe stands. Every move runs at a feed: prove it out at reduced feed override with the probe clear of the part.</source>
        <translation>场景中对表面的循环，以普通测量移动写出：其策略、进给率、回退距离和起始距离，即您在此调优的值，而非厂商的循环调用。测头位于表面前方的起始距离处。每个移动都是从测头当前位置出发的增量移动。所有移动都以进给率运行：请在降低的进给倍率下、测头远离工件时试运行。</translation>
    </message>
    <message>
        <source>The scenario&apos;s cycle on its feature, as plain probing moves: its strategy, feeds, backoff and start distance, the values you tuned here, not a maker&apos;s cycle call. The probe starts at the feature&apos;s centre (over it for a boss or web) and every move toward the part is protected: a touch on the way is an obstruction. Every move is incremental from where the probe stands. Prove it out at reduced feed override (a boss&apos;s or web&apos;s lifts are rapids: reduced rapid override too) with the probe clear of the part.</source>
        <translation>场景中对其特征的循环，以普通测量移动写出：其策略、进给率、回退距离和起始距离，即您在此调优的值，而非厂商的循环调用。测头从特征中心出发（圆柱或凸台则在其上方），每个朝向工件的移动都是保护移动：途中的触测即为障碍。每个移动都是从测头当前位置出发的增量移动。请在降低的进给倍率下（圆柱或凸台上方的抬起为快速移动：还需降低快速倍率）、测头远离工件时试运行。</translation>
    </message>
    <message>
        <source>Probe input</source>
        <translation>测头输入</translation>
    </message>
    <message>
        <source>1, rising edge</source>
        <translation>1，上升沿</translation>
    </message>
    <message>
        <source>1, falling edge</source>
        <translation>1，下降沿</translation>
    </message>
    <message>
        <source>2, rising edge</source>
        <translation>2，上升沿</translation>
    </message>
    <message>
        <source>2, falling edge</source>
        <translation>2，下降沿</translation>
    </message>
    <message>
        <source>Which probe input the measuring moves use (Siemens: MEAS=1, -1, 2 or -2), as the machine&apos;s builder wired it: falling edge for a probe whose signal falls when it triggers; the CLI&apos;s --probe-input.</source>
        <translation>测量移动使用哪个测头输入（Siemens：MEAS=1、-1、2 或 -2），按机床制造商的接线：触发时信号下降的测头选下降沿；对应 CLI 的 --probe-input。</translation>
    </message>
</context>
<context>
    <name>probecycle::ui::QuantityEdit</name>
    <message>
        <source>Range: %1 to %2 %3</source>
        <translation>范围：%1 至 %2 %3</translation>
    </message>
</context>
<context>
    <name>probecycle::ui::Readouts</name>
    <message>
        <source>Cycle time</source>
        <translation>循环时间</translation>
    </message>
    <message>
        <source>Overtravel</source>
        <translation>过行程</translation>
    </message>
    <message>
        <source>Trigger speed</source>
        <translation>触发速度</translation>
    </message>
    <message>
        <source>Uncertainty (k = 2)</source>
        <translation>不确定度 (k = 2)</translation>
    </message>
    <message>
        <source>Recommended backoff</source>
        <translation>推荐回退距离</translation>
    </message>
    <message>
        <source>Knee of the curve</source>
        <translation>曲线拐点</translation>
    </message>
    <message>
        <source>Worst distance beyond the surface where the axis stops: pretravel + trigger speed × (interface + controller + full scan period) + braking distance.</source>
        <translation>轴停止处超出表面的最大距离：预行程 + 触发速度 × (接口 + 控制器 + 完整扫描周期) + 制动距离。</translation>
    </message>
    <message>
        <source>Speed when the measuring touch triggers; lower than programmed if the touch happens while accelerating.</source>
        <translation>测量触测触发时的速度；如果在加速过程中触测，则低于编程值。</translation>
    </message>
    <message>
        <source>invalid scenario</source>
        <translation>场景无效</translation>
    </message>
    <message>
        <source>target %1</source>
        <translation>目标 %1</translation>
    </message>
    <message>
        <source>set %1</source>
        <translation>当前 %1</translation>
    </message>
    <message>
        <source>for two-touch</source>
        <translation>用于两次触测</translation>
    </message>
    <message>
        <source>cycle %1</source>
        <translation>循环 %1</translation>
    </message>
    <message>
        <source>Δ %1 vs baseline</source>
        <translation>与基准相差 %1</translation>
    </message>
    <message>
        <source>%1 % of %2</source>
        <translation>为 %2 的 %1 %</translation>
    </message>
    <message>
        <source>as programmed</source>
        <translation>与编程值相同</translation>
    </message>
    <message>
        <source>%1 % of %2, 2nd touch</source>
        <translation>为 %2 的 %1 %，第二次触测</translation>
    </message>
    <message>
        <source>Total time of the probing cycle, all touches and moves. &quot;Invalid&quot; when the cycle cannot run as set (backoff too small, overtravel over the probe&apos;s limit): then it has no cycle time to compare.</source>
        <translation>测量循环的总时间，包括所有触测和移动。循环无法按设定运行时（回退距离太小、过行程超过测头极限）显示“无效”：此时没有可比较的循环时间。</translation>
    </message>
    <message>
        <source>The lowest probing feed whose cycle time is within the knee tolerance (1 % by default) of the best, among the valid cycles (overtravel under the probe&apos;s limit): faster buys almost no time.</source>
        <translation>在有效循环（过行程低于测头极限）中，循环时间在最佳值的拐点容差（默认 1 %）以内的最低探测进给率：更快几乎不再节省时间。</translation>
    </message>
    <message>
        <source>Invalid</source>
        <translation>无效</translation>
    </message>
    <message>
        <source>Two-touch: from the backoff&apos;s reference (where the probe stopped, or the recorded trigger position) the larger of the reseat distance and the distance to reach the measuring feed. Less risks a probe that has not reseated; more is approached again at the slow measuring feed.</source>
        <translation>两次触测：从回退起点（停止处或记录的触发位置）算起，取复位距离与加速到测量进给率所需距离中的较大者。小于此值测头可能未复位；大于此值的部分要以慢速测量进给率重新接近。</translation>
    </message>
    <message>
        <source>At %1 % feed override the probe stops %2 past the surface: %3 % of the probe&apos;s %4 limit. Every overtravel check holds at that override (Highest feed override).</source>
        <translation>在 %1 % 进给倍率下，测头停在表面后 %2 处：为测头极限 %4 的 %3 %。所有过行程检查都按该倍率进行（最高进给倍率）。</translation>
    </message>
    <message>
        <source>%1 % of limit at %2 %, 2nd touch</source>
        <translation>%1 %（倍率 %2 %），第二次</translation>
    </message>
    <message>
        <source>%1 % of limit at %2 %</source>
        <translation>%1 %（倍率 %2 %）</translation>
    </message>
    <message>
        <source>Expanded (k = 2) uncertainty of the measured point: the trigger&apos;s part (the scan-period range and the probe&apos;s repeatability, averaged over repeats) combined with the probe&apos;s lobing, the calibration artefact, the machine&apos;s repeatability and the thermal drift. The value&apos;s tooltip shows the budget.</source>
        <translation>测量点的扩展不确定度 (k = 2)：触发部分（扫描周期范围和测头重复性，按重复次数取平均）与测头各向异性、校准标准器、机床重复性和热漂移合成。数值的提示显示预算。</translation>
    </message>
    <message>
        <source>trigger %1</source>
        <translation>触发 %1</translation>
    </message>
    <message>
        <source>&lt;p&gt;The measurement&apos;s uncertainty budget: each term&apos;s standard uncertainty, combined as the root sum of squares and expanded with k = 2. Set the terms under Machine and Probe.&lt;/p&gt;</source>
        <translation>&lt;p&gt;测量的不确定度预算：各项的标准不确定度按平方和的平方根合成，并以 k = 2 扩展。各项在“机床”和“测头”中设置。&lt;/p&gt;</translation>
    </message>
    <message>
        <source>%1 % of programmed</source>
        <translation>编程值的 %1 %</translation>
    </message>
</context>
<context>
    <name>probecycle::ui::ReportDetailsDialog</name>
    <message>
        <source>Customer</source>
        <translation>客户</translation>
    </message>
    <message>
        <source>Machine</source>
        <translation>机床</translation>
    </message>
    <message>
        <source>Part</source>
        <translation>零件</translation>
    </message>
    <message>
        <source>Author</source>
        <translation>作者</translation>
    </message>
    <message>
        <source>Notes</source>
        <translation>备注</translation>
    </message>
    <message>
        <source>Report Details</source>
        <translation>报告信息</translation>
    </message>
    <message>
        <source>Shown at the top of the PDF report&apos;s first page, with the date and the program&apos;s version. Saved in the project file.</source>
        <translation>显示在 PDF 报告第一页的开头，并附日期和程序版本。保存在项目文件中。</translation>
    </message>
</context>
<context>
    <name>probecycle::ui::StatusText</name>
    <message>
        <source>Unexpected error: %1</source>
        <extracomment>an exception the window does not expect (out of memory...); %1 its English text</extracomment>
        <translation>意外错误：%1</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>已保存 %1</translation>
    </message>
</context>
<context>
    <name>probecycle::ui::WarningsPanel</name>
    <message>
        <source>No warnings: the cycle is within the probe&apos;s limits.</source>
        <translation>无警告：循环在测头极限之内。</translation>
    </message>
    <message>
        <source>Invalid scenario</source>
        <translation>场景无效</translation>
    </message>
    <message>
        <source>Set backoff to %1</source>
        <translation>将回退距离设为 %1</translation>
    </message>
    <message>
        <source>Drop feed to the knee, %1</source>
        <translation>将进给率降至拐点 %1</translation>
    </message>
    <message>
        <source>Start %1 out</source>
        <translation>起点设在 %1 外</translation>
    </message>
    <message>
        <source>Drop feed to %1</source>
        <translation>将进给率降至 %1</translation>
    </message>
    <message>
        <source>Error</source>
        <translation>错误</translation>
    </message>
    <message>
        <source>Warning</source>
        <translation>警示</translation>
    </message>
    <message>
        <source>Note</source>
        <translation>提示</translation>
    </message>
    <message>
        <source>Search %1 past the surface</source>
        <translation>搜索到表面之后 %1</translation>
    </message>
    <message>
        <source>Position at %1</source>
        <translation>定位进给率 %1</translation>
    </message>
    <message>
        <source>%1, backoff %2</source>
        <extracomment>%1 what the fix sets (&quot;Start 15.680 mm out&quot;), %2 the backoff it needs with it</extracomment>
        <translation>%1，回退距离 %2</translation>
    </message>
</context>
</TS>
