#include "ui/comparison/comparison_tab.h"

#include <QAbstractTableModel>
#include <QDir>
#include <QEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QPushButton>
#include <QScrollBar>
#include <QSignalBlocker>
#include <QSplitter>
#include <QStandardPaths>
#include <QTableView>
#include <QTableWidget>
#include <QToolButton>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>

#include "core/common/csv_reader.h"
#include "core/common/file_io.h"
#include "core/common/vector_state.h"
#include "core/comparison/comparison_files.h"
#include "core/comparison/comparison_input.h"
#include "core/comparison/comparison_project.h"
#include "core/comparison/comparison_report.h"
#include "core/comparison/comparison_simulator.h"
#include "ui/common/file_write.h"
#include "ui/common/parameter_info.h"
#include "ui/common/plot_view.h"
#include "ui/common/status_text.h"
#include "ui/common/text_format.h"
#include "ui/common/unit_spin_box.h"
#include "ui/common/warning_list.h"

namespace probecycle::ui {

namespace {

// The colour classes of the map, from far below the band to far above it:
// out of tolerance (dark), within the band in three steps each side of a
// centre class. Edges in units of the tolerance.
constexpr std::array<double, 6> kClassEdges = {-1.0, -0.6, -0.2, 0.2, 0.6, 1.0};
const std::array<QColor, 7> kClassColours = {QColor(0x08, 0x30, 0x6b), QColor(0x21, 0x71, 0xb5),
                                             QColor(0x6b, 0xae, 0xd6), QColor(0x31, 0xa3, 0x54),
                                             QColor(0xfd, 0xae, 0x6b), QColor(0xe6, 0x55, 0x0d),
                                             QColor(0xa5, 0x0f, 0x15)};
const QColor kDirectColour{0x7f, 0x7f, 0x7f};
const QColor kDeviationColour{0x1f, 0x77, 0xb4};
const QColor kBandColour{0xc0, 0x39, 0x2b};
constexpr int kHistogramBins = 24;
constexpr double kArcsecPerRad = 180.0 * 3600.0 / std::numbers::pi;

int class_of(double deviation_mm, double tolerance_mm) {
    const double t = deviation_mm / tolerance_mm;
    int c = 0;
    while (c < static_cast<int>(kClassEdges.size()) &&
           t > kClassEdges[static_cast<std::size_t>(c)]) {
        ++c;
    }
    return c;
}

QString um(double mm, int decimals = 1) {
    return format_number(mm * 1000.0, decimals) + QChar(0x00A0) + unit_um();
}

// What tells a file's content apart without reading it: its path, its
// modification time and its size (an empty path: a file not given).
struct FileStamp {
    std::string path;
    std::filesystem::file_time_type modified{};
    std::uintmax_t size{0};

    bool operator==(const FileStamp&) const = default;
};

// Nullopt for a file that cannot be stamped (missing, a pipe): read each time.
std::optional<FileStamp> stamp_of(const std::string& path) {
    FileStamp stamp{path};
    if (path.empty()) return stamp;
    std::error_code error;
    const std::filesystem::path file = path_from_utf8(path);
    stamp.modified = std::filesystem::last_write_time(file, error);
    if (error) return std::nullopt;
    stamp.size = std::filesystem::file_size(file, error);
    if (error) return std::nullopt;
    return stamp;
}

}  // namespace

// The files last read and their content: a change of a setting reruns the
// comparison without reading them again.
struct ComparisonTab::FileCache {
    std::array<std::optional<FileStamp>, kComparisonFiles> stamps;
    std::optional<ComparisonInput> input;
};

// The points, worst first, formatted only when shown: a table widget would
// hold an item per cell, over a million for the 200 000 points a plan file
// can have.
class PointTableModel final : public QAbstractTableModel {
  public:
    struct Row {
        int point{0};  // 1-based, in the plan's order
        double x_mm{0.0}, y_mm{0.0}, z_mm{0.0};
        double deviation_mm{0.0}, system_error_mm{0.0}, direct_mm{0.0};
    };

    using QAbstractTableModel::QAbstractTableModel;

    void set_rows(std::vector<Row> rows, double tolerance_mm) {
        beginResetModel();
        rows_ = std::move(rows);
        tolerance_mm_ = tolerance_mm;
        endResetModel();
    }
    void set_headers(QStringList headers) {
        headers_ = std::move(headers);
        emit headerDataChanged(Qt::Horizontal, 0, columnCount() - 1);
    }
    int point_at(int row) const { return rows_[static_cast<std::size_t>(row)].point; }

    int rowCount(const QModelIndex& parent = {}) const override {
        return parent.isValid() ? 0 : static_cast<int>(rows_.size());
    }
    int columnCount(const QModelIndex& parent = {}) const override {
        return parent.isValid() ? 0 : 7;
    }
    QVariant data(const QModelIndex& index, int role) const override {
        if (!index.isValid() || index.row() >= rowCount()) return {};
        const Row& r = rows_[static_cast<std::size_t>(index.row())];
        switch (role) {
            case Qt::DisplayRole:
                switch (index.column()) {
                    case 0:
                        return QLocale().toString(r.point);
                    case 1:
                        return format_number(r.x_mm, 2);
                    case 2:
                        return format_number(r.y_mm, 2);
                    case 3:
                        return format_number(r.z_mm, 2);
                    case 4:
                        return um(r.deviation_mm);
                    case 5:
                        return um(r.system_error_mm);
                    default:
                        return um(r.direct_mm);
                }
            case Qt::TextAlignmentRole:
                return QVariant::fromValue(Qt::Alignment(Qt::AlignRight | Qt::AlignVCenter));
            case Qt::ForegroundRole:
                if (index.column() == 4 && tolerance_mm_ > 0.0 &&
                    std::abs(r.deviation_mm) > tolerance_mm_) {
                    return kBandColour;
                }
                return {};
            default:
                return {};
        }
    }
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override {
        if (orientation == Qt::Horizontal && role == Qt::DisplayRole && section >= 0 &&
            section < headers_.size()) {
            return headers_[section];
        }
        return QAbstractTableModel::headerData(section, orientation, role);
    }

  private:
    std::vector<Row> rows_;
    double tolerance_mm_{0.0};
    QStringList headers_;
};

ComparisonTab::ComparisonTab(QWidget* parent)
    : Page(parent), file_cache_(std::make_unique<FileCache>()) {
    setObjectName(QStringLiteral("comparison"));
    auto* input_widget = new QWidget(this);
    auto* input_column = new QVBoxLayout(input_widget);
    input_column->setContentsMargins(0, 0, 0, 0);
    input_column->addWidget(build_input_group());
    input_column->addStretch(1);
    input_widget->setFixedWidth(350);

    auto* root = new QHBoxLayout(this);
    root->addWidget(input_widget);
    root->addWidget(build_charts(), 1);
    root->addWidget(build_result_column());

    connect(run_button_, &QPushButton::clicked, this, [this] { run(); });
    connect(simulate_button_, &QPushButton::clicked, this, &ComparisonTab::simulate_dialog);
    connect(open_button_, &QPushButton::clicked, this, &ComparisonTab::open_project_dialog);
    connect(save_button_, &QPushButton::clicked, this, &ComparisonTab::save_project_dialog);
    connect(export_button_, &QPushButton::clicked, this, &ComparisonTab::export_dialog);
    for (int i = 0; i < kInputFiles; ++i) {
        connect(file_buttons_[static_cast<std::size_t>(i)], &QToolButton::clicked, this,
                [this, i] { choose_file(static_cast<InputFile>(i)); });
    }
    for (UnitSpinBox* box : {axis_x_, axis_y_, angle_}) {
        connect(box, &QDoubleSpinBox::valueChanged, this, &ComparisonTab::rerun_if_shown);
    }
    connect(tolerance_, &QDoubleSpinBox::valueChanged, this, [this] {
        if (!result_) {
            draw_map();
            draw_histogram();
        }
        rerun_if_shown();
    });
    retranslate();
    watch_inputs();
}

ComparisonTab::~ComparisonTab() = default;

QGroupBox* ComparisonTab::build_input_group() {
    input_group_ = new QGroupBox(this);
    format_hint_ = new QLabel(input_group_);
    format_hint_->setWordWrap(true);
    auto* files = new QGridLayout;
    for (int i = 0; i < kInputFiles; ++i) {
        const auto k = static_cast<std::size_t>(i);
        file_labels_[k] = new QLabel(input_group_);
        file_labels_[k]->setWordWrap(true);  // long Russian labels take two lines
        file_edits_[k] = new QLineEdit(input_group_);
        file_edits_[k]->setObjectName(QStringLiteral("comparison-file-%1").arg(i));
        file_edits_[k]->setClearButtonEnabled(true);
        file_labels_[k]->setBuddy(file_edits_[k]);
        file_buttons_[k] = new QToolButton(input_group_);
        file_buttons_[k]->setText(QStringLiteral("…"));
        files->addWidget(file_labels_[k], 2 * i, 0, 1, 2);
        files->addWidget(file_edits_[k], 2 * i + 1, 0);
        files->addWidget(file_buttons_[k], 2 * i + 1, 1);
    }
    axis_x_ = new UnitSpinBox(-kMaxCoordinate_mm, kMaxCoordinate_mm, 4, 0.0, input_group_);
    axis_x_->set_unit(unit_mm);
    axis_y_ = new UnitSpinBox(-kMaxCoordinate_mm, kMaxCoordinate_mm, 4, 0.0, input_group_);
    axis_y_->set_unit(unit_mm);
    angle_ =
        new UnitSpinBox(kMinComparisonAngle_deg, kMaxComparisonAngle_deg, 3, 180.0, input_group_);
    angle_->set_unit([] { return QStringLiteral("°"); });
    // The tolerance in µm: a few micrometres to a few tenths.
    tolerance_ = new UnitSpinBox(1e-4, kMaxTolerance_mm, 1, 0.01, input_group_, 1000.0);
    tolerance_->set_unit(unit_um);
    tolerance_->setObjectName(QStringLiteral("comparison-tolerance"));
    axis_x_label_ = new QLabel(input_group_);
    axis_x_label_->setBuddy(axis_x_);
    axis_y_label_ = new QLabel(input_group_);
    axis_y_label_->setBuddy(axis_y_);
    angle_label_ = new QLabel(input_group_);
    angle_label_->setBuddy(angle_);
    tolerance_label_ = new QLabel(input_group_);
    tolerance_label_->setBuddy(tolerance_);
    auto* form = new QFormLayout;
    form->setFieldGrowthPolicy(QFormLayout::FieldsStayAtSizeHint);
    form->addRow(axis_x_label_, axis_x_);
    form->addRow(axis_y_label_, axis_y_);
    form->addRow(angle_label_, angle_);
    form->addRow(tolerance_label_, tolerance_);

    run_button_ = new QPushButton(input_group_);
    run_button_->setDefault(true);
    simulate_button_ = new QPushButton(input_group_);
    open_button_ = new QPushButton(input_group_);
    save_button_ = new QPushButton(input_group_);
    error_label_ = new QLabel(input_group_);
    error_label_->setObjectName(QStringLiteral("comparison-error"));
    error_label_->setWordWrap(true);
    error_label_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    error_label_->hide();
    auto* project_row = new QHBoxLayout;
    project_row->addWidget(open_button_);
    project_row->addWidget(save_button_);
    auto* run_row = new QHBoxLayout;
    run_row->addWidget(simulate_button_);
    run_row->addStretch(1);
    run_row->addWidget(run_button_);

    auto* column = new QVBoxLayout(input_group_);
    column->addWidget(format_hint_);
    column->addLayout(files);
    column->addLayout(form);
    column->addLayout(project_row);
    column->addLayout(run_row);
    column->addWidget(error_label_);
    return input_group_;
}

QWidget* ComparisonTab::build_charts() {
    map_ = new PlotView(this);
    map_->setObjectName(QStringLiteral("comparison-map"));
    map_->set_x_axis({PlotView::Scale::linear, {}, QStringLiteral("%.4g"), {}});
    map_->set_y_axis(PlotView::Side::left,
                     {PlotView::Scale::linear, {}, QStringLiteral("%.4g"), {}});
    // One marker series per colour class: the legend, beside the map, is
    // the colour scale with the tolerance band.
    map_->set_legend_beside(true);
    for (std::size_t c = 0; c < class_curves_.size(); ++c) {
        class_curves_[c] = map_->add_markers({QStringLiteral(" "), kClassColours[c]}, 11.0);
    }
    histogram_ = new PlotView(this);
    histogram_->setObjectName(QStringLiteral("comparison-histogram"));
    histogram_->set_x_axis({PlotView::Scale::linear, {}, QStringLiteral("%.3g"), {}});
    histogram_->set_y_axis(PlotView::Side::left,
                           {PlotView::Scale::linear, {}, QStringLiteral("%.0f"), {}});
    QColor direct_fill = kDirectColour;
    direct_fill.setAlpha(90);
    QColor deviation_fill = kDeviationColour;
    deviation_fill.setAlpha(140);
    direct_area_ = histogram_->add_area({QStringLiteral(" "), kDirectColour, 1.0}, direct_fill);
    deviation_area_ =
        histogram_->add_area({QStringLiteral(" "), kDeviationColour, 1.5}, deviation_fill);
    band_low_ =
        histogram_->add_line({QStringLiteral(" "), kBandColour, 1.5, PlotView::Dash::dashed});
    band_high_ = histogram_->add_line({{}, kBandColour, 1.5, PlotView::Dash::dashed});
    auto* splitter = new QSplitter(Qt::Vertical, this);
    splitter->setChildrenCollapsible(false);
    splitter->addWidget(map_);
    splitter->addWidget(histogram_);
    splitter->setStretchFactor(0, 3);
    splitter->setStretchFactor(1, 2);
    return splitter;
}

QWidget* ComparisonTab::build_result_column() {
    result_group_ = new QGroupBox(this);
    QFont bold = result_group_->font();
    bold.setBold(true);
    const auto title = [this, &bold] {
        auto* label = new QLabel(result_group_);
        label->setFont(bold);
        label->setWordWrap(true);  // a long title (Russian) takes two lines, not the charts' width
        return label;
    };
    const auto table = [this](int rows, int columns, const char* name) {
        auto* t = new QTableWidget(rows, columns, result_group_);
        t->setObjectName(QString::fromLatin1(name));
        t->setEditTriggers(QAbstractItemView::NoEditTriggers);
        t->verticalHeader()->setVisible(false);
        t->horizontalHeader()->setStretchLastSection(true);
        t->setSelectionBehavior(QAbstractItemView::SelectRows);
        t->verticalHeader()->setDefaultSectionSize(t->fontMetrics().height() + 6);
        if (rows > 0) {
            // Every row shows; room is kept for a horizontal scroll bar, which the longer
            // Russian labels need, so that it never hides the last row.
            t->setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
            t->setFixedHeight(t->horizontalHeader()->sizeHint().height() +
                              rows * t->verticalHeader()->defaultSectionSize() +
                              2 * t->frameWidth() + t->horizontalScrollBar()->sizeHint().height());
        } else {
            t->setMinimumHeight(120);
        }
        return t;
    };
    c_axis_title_ = title();
    c_axis_table_ = table(6, 3, "comparison-c-axis");
    summary_title_ = title();
    summary_table_ = table(3, 5, "comparison-summary");
    warnings_title_ = title();
    warnings_ = new WarningList(result_group_);
    warnings_->setObjectName(QStringLiteral("comparison-warnings"));
    points_title_ = title();
    point_model_ = new PointTableModel(this);
    point_table_ = new QTableView(result_group_);
    point_table_->setObjectName(QStringLiteral("comparison-points"));
    point_table_->setModel(point_model_);
    point_table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    point_table_->verticalHeader()->setVisible(false);
    point_table_->horizontalHeader()->setStretchLastSection(true);
    point_table_->setSelectionBehavior(QAbstractItemView::SelectRows);
    // Rows of one height, so the view never measures them one by one.
    point_table_->verticalHeader()->setSectionResizeMode(QHeaderView::Fixed);
    point_table_->verticalHeader()->setDefaultSectionSize(point_table_->fontMetrics().height() + 6);
    point_table_->setMinimumHeight(120);
    export_button_ = new QPushButton(result_group_);
    export_button_->setEnabled(false);
    export_status_ = new QLabel(result_group_);
    export_status_->setWordWrap(true);
    export_status_->hide();
    auto* export_row = new QHBoxLayout;
    export_row->addStretch(1);
    export_row->addWidget(export_button_);
    auto* column = new QVBoxLayout(result_group_);
    column->addWidget(c_axis_title_);
    column->addWidget(c_axis_table_);
    column->addWidget(summary_title_);
    column->addWidget(summary_table_);
    column->addWidget(warnings_title_);
    column->addWidget(warnings_);
    column->addWidget(points_title_);
    column->addWidget(point_table_, 1);
    column->addWidget(export_status_);
    column->addLayout(export_row);
    result_group_->setMinimumWidth(400);
    result_group_->setMaximumWidth(500);
    return result_group_;
}

void ComparisonTab::retranslate() {
    input_group_->setTitle(tr("Files and setup"));
    format_hint_->setText(
        tr("CSV files with a header row, in the plan's order: the plan "
           "<code>x_mm,y_mm,z_mm,i,j,k</code> (outward unit normal), points "
           "<code>x_mm,y_mm,z_mm</code> (or DMIS <code>PTMEAS/CART</code>), the block "
           "<code>face,x_mm,y_mm,z_mm</code> with faces A, B, C."));
    const std::array<QString, kInputFiles> labels = {
        tr("Inspection plan"),
        tr("Reference part, CMM points"),
        tr("Test part, on-machine points at C = 0"),
        tr("Reference part, on-machine points after the turn"),
        tr("Block at C = 0 (optional)"),
        tr("Block after the turn (optional)")};
    const std::array<QString, kInputFiles> tips = {
        tr("Nominal points and outward unit normals (the side the probe comes from), in "
           "machine coordinates at the measuring position (C = 0)."),
        tr("The reference part as the CMM measured it, one point per plan point, in the "
           "plan's coordinates."),
        tr("The test part probed on the machine along the plan, C at 0."),
        tr("The reference part probed along the same plan after C turned by the angle: at "
           "the same place of the machine as the test part."),
        tr("Three faces of a block's corner, touched at C = 0: they give the C axis's six "
           "errors. Without the block the C axis is taken as exact."),
        tr("The same three faces touched after the turn.")};
    for (std::size_t k = 0; k < labels.size(); ++k) {
        file_labels_[k]->setText(labels[k]);
        file_edits_[k]->setToolTip(tips[k]);
        file_buttons_[k]->setToolTip(tr("Choose a file…"));
    }
    axis_x_label_->setText(tr("C axis X"));
    axis_x_->setToolTip(tr("Where the C axis is, in machine X."));
    axis_y_label_->setText(tr("C axis Y"));
    axis_y_->setToolTip(tr("Where the C axis is, in machine Y."));
    angle_label_->setText(tr("Comparison angle"));
    angle_->setToolTip(
        tr("How far C turns between the two measurements (180° for parts "
           "clamped opposite each other)."));
    tolerance_label_->setText(tr("Tolerance (±)"));
    tolerance_->setToolTip(tr("Half-width of the tolerance band about the nominal surface."));
    for (UnitSpinBox* box : {axis_x_, axis_y_, angle_, tolerance_}) box->retranslate();
    run_button_->setText(tr("Run"));
    simulate_button_->setText(tr("Simulate example data"));
    simulate_button_->setToolTip(
        tr("Write a simulated data set with a known truth (truth.csv) to a folder and run it."));
    open_button_->setText(tr("Open project…"));
    save_button_->setText(tr("Save project…"));

    map_->set_title(tr("Deviation of the test part"));
    map_->set_x_axis(
        {PlotView::Scale::linear, tr("X [%1]").arg(unit_mm()), QStringLiteral("%.4g"), {}});
    map_->set_y_axis(
        PlotView::Side::left,
        {PlotView::Scale::linear, tr("Y [%1]").arg(unit_mm()), QStringLiteral("%.4g"), {}});
    histogram_->set_title(tr("Deviations: direct OMM and comparison"));
    histogram_->set_x_axis(
        {PlotView::Scale::linear, tr("Deviation [%1]").arg(unit_um()), QStringLiteral("%.3g"), {}});
    histogram_->set_y_axis(PlotView::Side::left,
                           {PlotView::Scale::linear, tr("Points"), QStringLiteral("%.0f"), {}});
    histogram_->set_name(direct_area_, tr("Direct OMM"));
    histogram_->set_name(deviation_area_, tr("Comparison"));
    histogram_->set_name(band_low_, tr("Tolerance"));

    result_group_->setTitle(tr("Result"));
    c_axis_title_->setText(tr("C-axis errors"));
    c_axis_table_->setHorizontalHeaderLabels({tr("Error"), tr("Value"), tr("Uncertainty")});
    // The unit in the title, the cells' numbers alone: every column shows in
    // the result column's width, the count out of tolerance included.
    summary_title_->setText(tr("Direct OMM against the comparison [%1]").arg(unit_um()));
    summary_table_->setHorizontalHeaderLabels(
        {QString(), tr("Min"), tr("Max"), tr("RMS"), tr("Out of tol.")});
    warnings_title_->setText(tr("Warnings"));
    warnings_->set_empty_text(tr("No warnings."));
    points_title_->setText(tr("Points, worst first"));
    point_model_->set_headers({tr("Point"), tr("X"), tr("Y"), tr("Z"), tr("Deviation"),
                               tr("System error"), tr("Direct OMM")});
    export_button_->setText(tr("Export report…"));
    if (!last_error_.isEmpty() && error_label_->isVisible()) {
        // The error was translated when it was made; a rerun would make it again.
        rerun_if_shown();
    }
    show_result();
}

void ComparisonTab::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) retranslate();
    QWidget::changeEvent(event);
}

void ComparisonTab::set_file(InputFile which, const QString& path) {
    file_edits_[static_cast<std::size_t>(which)]->setText(path);
}

QString ComparisonTab::file(InputFile which) const {
    return file_edits_[static_cast<std::size_t>(which)]->text().trimmed();
}

void ComparisonTab::set_c_axis(double x_mm, double y_mm) {
    const QSignalBlocker block_x(axis_x_);
    const QSignalBlocker block_y(axis_y_);
    axis_x_->set_internal_value(x_mm);
    axis_y_->set_internal_value(y_mm);
}

void ComparisonTab::set_angle_deg(double angle_deg) {
    const QSignalBlocker block(angle_);
    angle_->set_internal_value(angle_deg);
}

void ComparisonTab::set_tolerance_mm(double tolerance_mm) {
    tolerance_->set_internal_value(tolerance_mm);
}

double ComparisonTab::tolerance_mm() const {
    return tolerance_->internal_value();
}

void ComparisonTab::set_error(const QString& text) {
    last_error_ = text;
    if (text.isEmpty()) {
        error_label_->hide();
    } else {
        show_error(error_label_, text);
    }
}

bool ComparisonTab::run() {
    try {
        ComparisonInput input = read_files();
        input.c_axis = {axis_x_->internal_value(), axis_y_->internal_value(),
                        angle_->internal_value()};
        input.tolerance_mm = tolerance_->internal_value();
        clear_vector_upper_state();  // what Qt painted may have left them in use
        ComparisonResult result = run_comparison(input);
        input_ = std::move(input);
        result_ = std::move(result);
    } catch (const ComparisonFileError& e) {
        set_error(file_error_text(e));
        return false;
    } catch (const std::exception& e) {
        set_error(error_text(e));  // a FileError names the file already
        return false;
    }
    set_error({});
    export_status_->hide();
    show_result();
    return true;
}

ComparisonInput ComparisonTab::read_files() {
    const auto path = [this](InputFile which) { return core_path(file(which)); };
    const ComparisonFiles files{path(InputFile::plan),     path(InputFile::reference_cmm),
                                path(InputFile::test_omm), path(InputFile::reference_omm),
                                path(InputFile::block_c0), path(InputFile::block_c180)};
    std::array<std::optional<FileStamp>, kComparisonFiles> stamps;
    for (std::size_t k = 0; k < kComparisonFiles; ++k) {
        stamps[k] = stamp_of(files.path(static_cast<ComparisonFile>(k)));
    }
    const bool stamped =
        std::all_of(stamps.begin(), stamps.end(), [](const auto& s) { return s.has_value(); });
    if (stamped && file_cache_->input && stamps == file_cache_->stamps) {
        return *file_cache_->input;
    }
    file_cache_->input.reset();
    ComparisonInput input = read_comparison_files(files);
    if (stamped) {
        file_cache_->stamps = stamps;
        file_cache_->input = input;
    }
    return input;
}

QString ComparisonTab::file_error_text(const ComparisonFileError& error) const {
    switch (error.problem()) {
        case ComparisonFileError::Problem::not_given:
            return tr("Choose a file for “%1”.")
                .arg(file_labels_[static_cast<std::size_t>(error.file())]->text());
        case ComparisonFileError::Problem::one_block:
            return tr(
                "The block is needed at both angles: choose both block files, or "
                "neither.");
        case ComparisonFileError::Problem::refused:
            break;
    }
    QString cause;
    try {
        if (error.cause()) std::rethrow_exception(error.cause());
    } catch (const std::exception& e) {
        cause = error_text(e);
    }
    return QFileInfo(file(error.file())).fileName() + QStringLiteral(": ") + cause;
}

void ComparisonTab::rerun_if_shown() {
    if (result_ || !last_error_.isEmpty()) run();
}

bool ComparisonTab::simulate_example(const QString& folder) {
    QString dir = folder;
    if (dir.isEmpty()) {
        dir = QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) +
              QStringLiteral("/comparison_example");
    }
    if (!QDir().mkpath(dir)) {
        set_error(tr("Cannot make the folder %1.").arg(QDir::toNativeSeparators(dir)));
        return false;
    }
    const ComparisonDataSet example = simulate_comparison({});
    const ComparisonInput& in = example.input;
    const std::vector<ComparisonExampleFile> files = comparison_example_files(example);
    try {
        for (const ComparisonExampleFile& f : files) {
            write_file_atomically(
                core_path(dir + QLatin1Char('/') + QString::fromStdString(f.name)), f.text);
        }
    } catch (const std::exception& e) {
        set_error(error_text(e));
        return false;
    }
    for (int i = 0; i < kInputFiles; ++i) {
        set_file(static_cast<InputFile>(i),
                 dir + QLatin1Char('/') +
                     QString::fromStdString(files[static_cast<std::size_t>(i)].name));
    }
    set_c_axis(in.c_axis.x_mm, in.c_axis.y_mm);
    set_angle_deg(in.c_axis.angle_deg);
    set_remembered_folder(dir);
    return run();
}

std::optional<std::string> ComparisonTab::report_csv(ReportRows rows) {
    if (!result_) {
        show_live_error(export_status_, [this] {
            return last_error_ = tr("Nothing to export: run the comparison first.");
        });
        return std::nullopt;
    }
    ReportHeader header;
    header.date = report_date();
    header.subject = QFileInfo(file(InputFile::test_omm)).fileName().toStdString();
    return comparison_report_csv(input_, *result_, header, rows);
}

bool ComparisonTab::export_report(const QString& path, ReportRows rows) {
    const std::optional<std::string> csv = report_csv(rows);
    if (!csv) return false;
    try {
        write_file_atomically(core_path(path), *csv);
    } catch (const std::exception&) {
        show_live_error(export_status_,
                        [this, error = current_error_text()] { return last_error_ = error(); });
        return false;
    }
    remember_folder_of(path);
    show_saved(export_status_, path);
    return true;
}

ComparisonProject ComparisonTab::settings(const QString& base_folder) const {
    const QDir base(base_folder);
    const auto stored = [&](const QString& file) {
        if (file.isEmpty()) return std::string();
        return core_path(base_folder.isEmpty() ? file : base.relativeFilePath(file));
    };
    ComparisonProject project;
    project.plan = stored(file(InputFile::plan));
    project.reference_cmm = stored(file(InputFile::reference_cmm));
    project.test_omm = stored(file(InputFile::test_omm));
    project.reference_omm = stored(file(InputFile::reference_omm));
    project.block_c0 = stored(file(InputFile::block_c0));
    project.block_c180 = stored(file(InputFile::block_c180));
    project.c_axis_x_mm = axis_x_->internal_value();
    project.c_axis_y_mm = axis_y_->internal_value();
    project.angle_deg = angle_->internal_value();
    project.tolerance_mm = tolerance_->internal_value();
    return project;
}

bool ComparisonTab::restore(const ComparisonProject& project, const QString& base_folder) {
    const QDir base(base_folder);
    const auto absolute = [&](const std::string& file) {
        if (file.empty()) return QString();
        const QString name = QString::fromStdString(file);  // UTF-8, as core_path() gives
        return base_folder.isEmpty() ? name : QDir::cleanPath(base.absoluteFilePath(name));
    };
    set_file(InputFile::plan, absolute(project.plan));
    set_file(InputFile::reference_cmm, absolute(project.reference_cmm));
    set_file(InputFile::test_omm, absolute(project.test_omm));
    set_file(InputFile::reference_omm, absolute(project.reference_omm));
    set_file(InputFile::block_c0, absolute(project.block_c0));
    set_file(InputFile::block_c180, absolute(project.block_c180));
    set_c_axis(project.c_axis_x_mm, project.c_axis_y_mm);
    set_angle_deg(project.angle_deg);
    {
        const QSignalBlocker block(tolerance_);
        tolerance_->set_internal_value(project.tolerance_mm);
    }
    set_error({});
    const bool complete = !project.plan.empty() && !project.reference_cmm.empty() &&
                          !project.test_omm.empty() && !project.reference_omm.empty();
    if (complete) return run();
    clear_result();
    return true;
}

bool ComparisonTab::save_project(const QString& path) {
    const QString folder = QFileInfo(path).absolutePath();
    try {
        write_file_atomically(core_path(path), comparison_project_json(settings(folder)));
    } catch (const std::exception& e) {
        set_error(error_text(e));
        return false;
    }
    set_remembered_folder(folder);
    return true;
}

bool ComparisonTab::open_project(const QString& path) {
    ComparisonProject project;
    try {
        project = parse_comparison_project(read_text_file(core_path(path)));
    } catch (const FileError& e) {
        set_error(error_text(e));
        return false;
    } catch (const std::exception& e) {
        set_error(QFileInfo(path).fileName() + QStringLiteral(": ") + error_text(e));
        return false;
    }
    const QString folder = QFileInfo(path).absolutePath();
    set_remembered_folder(folder);
    return restore(project, folder);
}

QStringList ComparisonTab::warning_codes() const {
    return warnings_->codes();
}

QStringList ComparisonTab::summary_text() const {
    QStringList lines;
    for (int r = 0; r < summary_table_->rowCount(); ++r) {
        QStringList cells;
        for (int c = 0; c < summary_table_->columnCount(); ++c) {
            const QTableWidgetItem* item = summary_table_->item(r, c);
            cells << (item ? item->text() : QString());
        }
        lines << cells.first() + QStringLiteral(": ") + cells.mid(1).join(QStringLiteral(", "));
    }
    return lines;
}

QStringList ComparisonTab::c_axis_text() const {
    QStringList lines;
    for (int r = 0; r < c_axis_table_->rowCount(); ++r) {
        const auto text = [this, r](int c) {
            const QTableWidgetItem* item = c_axis_table_->item(r, c);
            return item ? item->text() : QString();
        };
        lines << text(0) + QStringLiteral(": ") + text(1) + QStringLiteral(" (") + text(2) +
                     QLatin1Char(')');
    }
    return lines;
}

QList<int> ComparisonTab::point_order() const {
    QList<int> order;
    for (int r = 0; r < point_model_->rowCount(); ++r) order << point_model_->point_at(r);
    return order;
}

int ComparisonTab::map_point_count() const {
    int count = 0;
    for (int curve : class_curves_) count += static_cast<int>(map_->point_count(curve));
    return count;
}

void ComparisonTab::show_result() {
    export_button_->setEnabled(result_.has_value());
    std::vector<WarningList::Item> items;
    if (result_) {
        for (const ComparisonWarning& w : result_->warnings) {
            WarningList::Item item;
            item.code = QString::fromStdString(w.code);
            item.severity = w.severity;
            item.message = translate(w.message);
            items.push_back(item);
        }
    }
    warnings_->show_items(items);
    fill_tables();
    draw_map();
    draw_histogram();
}

void ComparisonTab::clear_result() {
    result_.reset();
    show_result();
}

void ComparisonTab::fill_tables() {
    const auto set = [](QTableWidget* table, int row, int column, const QString& text,
                        bool right = true) {
        auto* item = new QTableWidgetItem(text);
        if (right) item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
        table->setItem(row, column, item);
    };
    // The C axis: angles in µrad and arcsec, offsets in µm.
    const std::array<QString, 6> names = {tr("εx (EAC)"), tr("εy (EBC)"), tr("εz (ECC)"),
                                          tr("δx (EXC)"), tr("δy (EYC)"), tr("δz (EZC)")};
    const QString urad = tr("µrad");
    for (int r = 0; r < 6; ++r) {
        set(c_axis_table_, r, 0, names[static_cast<std::size_t>(r)], false);
        if (!result_ || !result_->c_axis_identified) {
            set(c_axis_table_, r, 1, result_ ? tr("not identified") : QString());
            set(c_axis_table_, r, 2, QString());
            continue;
        }
        const double value = result_->c_axis.errors.vector()(r);
        const std::optional<CAxisErrors>& u = result_->c_axis.uncertainty;
        if (r < 3) {
            set(c_axis_table_, r, 1,
                format_number(value * 1e6, 2) + QChar(0x00A0) + urad + QStringLiteral(" (") +
                    format_number(value * kArcsecPerRad, 2) + QStringLiteral("″)"));
            set(c_axis_table_, r, 2,
                u ? QStringLiteral("± ") + format_number(u->vector()(r) * 1e6, 2) + QChar(0x00A0) +
                        urad
                  : tr("unknown"));
        } else {
            set(c_axis_table_, r, 1, um(value, 2));
            set(c_axis_table_, r, 2,
                u ? QStringLiteral("± ") + um(u->vector()(r), 2) : tr("unknown"));
        }
    }
    c_axis_table_->resizeColumnsToContents();

    const std::array<QString, 3> rows = {tr("Direct OMM"), tr("Comparison"), tr("System error")};
    for (int r = 0; r < 3; ++r) {
        set(summary_table_, r, 0, rows[static_cast<std::size_t>(r)], false);
        if (!result_) {
            for (int c = 1; c < 5; ++c) set(summary_table_, r, c, QString());
            continue;
        }
        const DeviationSummary& s = r == 0   ? result_->direct
                                    : r == 1 ? result_->deviation
                                             : result_->system_error;
        set(summary_table_, r, 1, format_number(s.min_mm * 1000.0, 1));
        set(summary_table_, r, 2, format_number(s.max_mm * 1000.0, 1));
        set(summary_table_, r, 3, format_number(s.rms_mm * 1000.0, 1));
        const std::optional<std::size_t>& out =
            r == 0 ? result_->direct_out_of_tolerance : result_->out_of_tolerance;
        set(summary_table_, r, 4,
            r < 2 && out ? QStringLiteral("%1 / %2").arg(
                               QLocale().toString(static_cast<qulonglong>(*out)),
                               QLocale().toString(static_cast<qulonglong>(result_->points.size())))
                         : QString());
    }
    summary_table_->resizeColumnsToContents();

    std::vector<PointTableModel::Row> point_rows;
    if (result_) {
        const std::vector<ComparisonPoint>& points = result_->points;
        point_rows.reserve(points.size());
        for (std::size_t i = 0; i < points.size(); ++i) {
            const ComparisonPoint& p = points[i];
            point_rows.push_back({static_cast<int>(i + 1), p.nominal.x(), p.nominal.y(),
                                  p.nominal.z(), p.deviation_mm, p.system_error_mm,
                                  p.direct_deviation_mm});
        }
        std::stable_sort(point_rows.begin(), point_rows.end(), [](const auto& a, const auto& b) {
            return std::abs(a.deviation_mm) > std::abs(b.deviation_mm);
        });
    }
    point_model_->set_rows(std::move(point_rows), input_.tolerance_mm.value_or(0.0));
    // The widths from the first rows (the worst, the widest numbers).
    point_table_->horizontalHeader()->setResizeContentsPrecision(100);
    point_table_->resizeColumnsToContents();
}

void ComparisonTab::draw_map() {
    std::array<QList<QPointF>, 7> classes;
    // Before a run the legend shows the classes of the tolerance set.
    double tolerance = result_ ? input_.tolerance_mm.value_or(0.0) : tolerance_mm();
    if (result_) {
        // Without a tolerance the classes span the largest deviation.
        if (!(tolerance > 0.0)) {
            tolerance =
                std::max(std::abs(result_->deviation.min_mm), std::abs(result_->deviation.max_mm));
            if (!(tolerance > 0.0)) tolerance = 0.001;
        }
        for (const ComparisonPoint& p : result_->points) {
            classes[static_cast<std::size_t>(class_of(p.deviation_mm, tolerance))].append(
                {p.nominal.x(), p.nominal.y()});
        }
    }
    // Legend: each class's range in µm, out of tolerance at the ends.
    const auto edge = [tolerance](std::size_t k) {
        return format_number(kClassEdges[k] * tolerance * 1000.0, 1);
    };
    for (std::size_t c = 0; c < classes.size(); ++c) {
        map_->set_points(class_curves_[c], classes[c]);
        QString name;
        if (c == 0) {
            name = tr("below %1 %2 (out)").arg(edge(0), unit_um());
        } else if (c == classes.size() - 1) {
            name = tr("above +%1 %2 (out)").arg(edge(kClassEdges.size() - 1), unit_um());
        } else {
            name = tr("%1 to %2 %3").arg(edge(c - 1), edge(c), unit_um());
        }
        map_->set_name(class_curves_[c], name);
    }
    if (result_ && !result_->points.empty()) {
        double x0 = result_->points.front().nominal.x();
        double x1 = x0;
        double y0 = result_->points.front().nominal.y();
        double y1 = y0;
        for (const ComparisonPoint& p : result_->points) {
            x0 = std::min(x0, p.nominal.x());
            x1 = std::max(x1, p.nominal.x());
            y0 = std::min(y0, p.nominal.y());
            y1 = std::max(y1, p.nominal.y());
        }
        // The part as it is: equal scales on X and Y.
        map_->set_equal_scales(
            QRectF(QPointF(x0, y0), QPointF(x1, y1)).adjusted(-0.5, -0.5, 0.5, 0.5));
    } else {
        map_->set_equal_scales({});
    }
}

void ComparisonTab::draw_histogram() {
    if (!result_ || result_->points.empty()) {
        // Before a run: the tolerance band set, on axes that read as counts.
        histogram_->set_area(direct_area_, {}, {});
        histogram_->set_area(deviation_area_, {}, {});
        const double band_um = tolerance_mm() * 1000.0;
        const double top = 10.0;
        histogram_->set_points(band_low_, {{-band_um, 0.0}, {-band_um, top}});
        histogram_->set_points(band_high_, {{band_um, 0.0}, {band_um, top}});
        histogram_->set_x_range(-1.5 * band_um, 1.5 * band_um);
        histogram_->set_y_range(PlotView::Side::left, 0.0, top);
        return;
    }
    // In µm, one range for both so that the two shapes compare.
    double lo = std::min(result_->direct.min_mm, result_->deviation.min_mm) * 1000.0;
    double hi = std::max(result_->direct.max_mm, result_->deviation.max_mm) * 1000.0;
    const double tolerance_um = input_.tolerance_mm.value_or(0.0) * 1000.0;
    if (tolerance_um > 0.0) {
        lo = std::min(lo, -tolerance_um);
        hi = std::max(hi, tolerance_um);
    }
    if (!(hi > lo)) hi = lo + 1.0;
    const double width = (hi - lo) / kHistogramBins;
    const auto steps = [&](double ComparisonPoint::*member, QList<QPointF>& upper,
                           QList<QPointF>& lower) {
        std::array<int, kHistogramBins> counts{};
        for (const ComparisonPoint& p : result_->points) {
            const int bin = std::clamp(static_cast<int>((p.*member * 1000.0 - lo) / width), 0,
                                       kHistogramBins - 1);
            ++counts[static_cast<std::size_t>(bin)];
        }
        int most = 0;
        for (int b = 0; b < kHistogramBins; ++b) {
            const double x0 = lo + b * width;
            const double c = counts[static_cast<std::size_t>(b)];
            upper << QPointF(x0, c) << QPointF(x0 + width, c);
            lower << QPointF(x0, 0.0) << QPointF(x0 + width, 0.0);
            most = std::max(most, counts[static_cast<std::size_t>(b)]);
        }
        return most;
    };
    QList<QPointF> direct_upper, direct_lower, deviation_upper, deviation_lower;
    const int most =
        std::max(steps(&ComparisonPoint::direct_deviation_mm, direct_upper, direct_lower),
                 steps(&ComparisonPoint::deviation_mm, deviation_upper, deviation_lower));
    histogram_->set_area(direct_area_, direct_upper, direct_lower);
    histogram_->set_area(deviation_area_, deviation_upper, deviation_lower);
    const double top = std::max(1.0, most * 1.1);
    if (tolerance_um > 0.0) {
        histogram_->set_points(band_low_, {{-tolerance_um, 0.0}, {-tolerance_um, top}});
        histogram_->set_points(band_high_, {{tolerance_um, 0.0}, {tolerance_um, top}});
    } else {
        histogram_->set_points(band_low_, {});
        histogram_->set_points(band_high_, {});
    }
    const double pad = 0.03 * (hi - lo);
    histogram_->set_x_range(lo - pad, hi + pad);
    histogram_->set_y_range(PlotView::Side::left, 0.0, top);
}

void ComparisonTab::choose_file(InputFile which) {
    const QString path = QFileDialog::getOpenFileName(
        this, file_labels_[static_cast<std::size_t>(which)]->text(), dialog_start(),
        tr("Point files (*.csv *.dmi *.dmis *.txt);;All files (*)"));
    if (path.isEmpty()) return;
    set_file(which, path);
    remember_folder_of(path);
}

void ComparisonTab::open_project_dialog() {
    const QString path = QFileDialog::getOpenFileName(
        this, tr("Open comparison project"), dialog_start(), tr("Comparison projects (*.json)"));
    if (!path.isEmpty()) open_project(path);
}

void ComparisonTab::save_project_dialog() {
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Save comparison project"), dialog_start(), tr("Comparison projects (*.json)"));
    if (!path.isEmpty()) save_project(path);
}

void ComparisonTab::export_dialog() {
    const QString path = QFileDialog::getSaveFileName(this, tr("Export comparison report"),
                                                      dialog_start(), tr("CSV files (*.csv)"));
    if (!path.isEmpty()) export_report(path);
}

void ComparisonTab::simulate_dialog() {
    simulate_example();
}

}  // namespace probecycle::ui
