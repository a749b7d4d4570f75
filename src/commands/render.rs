//! `massprop render FILE`: the body drawn as SVG (docs/render.md).

use super::Outcome;
use crate::analysis::Settings;
use crate::diag::Diagnostic;
use crate::output::drawing::{self, View};

#[derive(Debug, Clone, Default)]
pub struct Options {
    /// The part file; `-` is standard input.
    pub file: String,
    /// `-o FILE`.
    pub output: Option<String>,
    /// `--view`: one view, else all four.
    pub view: Option<View>,
    /// `--only`, `--about`, `--omega`, the includes: as `report`'s.
    pub settings: Settings,
    /// `--envelope`: the loading envelope's chart instead of the body.
    pub envelope: bool,
    /// A robot description's `--joints`.
    pub configuration: super::robot::Configuration,
}

pub fn run(o: &Options, terminal: &super::Terminal) -> Result<Outcome, Diagnostic> {
    let loaded = super::robot::load_any(&o.file, &o.settings, &o.configuration)?;
    let s = &loaded.summary;
    // Report axes to the file's frame: their rows are they in it.
    let to_file = |v: [f64; 3]| std::array::from_fn(|j| (0..3).map(|k| v[k] * s.axes[k][j]).sum());
    let f = loaded.model.units.factor(crate::units::Dim::LENGTH).value();
    let title = s.name.clone().unwrap_or_else(|| loaded.source.name.clone());
    let options = drawing::Options {
        view: o.view,
        about: loaded
            .analysis
            .about
            .map(|_| s.reference_point.map(|x| x / f)),
        omega: s.omega.map(to_file),
        title,
    };
    let chart = if o.envelope {
        Some(envelope_chart(&loaded, &o.settings, &options.title)?)
    } else {
        None
    };
    let read = super::files_of(&loaded);
    let stderr = super::accuracy_warnings(&loaded, terminal.stderr.colour);
    Ok(Outcome {
        stdout: super::Stdout::Drawing(Box::new(Drawing {
            model: loaded.model,
            summary: loaded.summary,
            options,
            chart,
        })),
        stderr,
        status: 0,
        read,
    })
}

/// A drawing handed over unwritten: written as it is made
/// (`drawing::write_svg`), to standard output or `-o`'s file, so that its
/// document is never all in memory.
#[derive(Debug, Clone)]
pub struct Drawing {
    model: crate::model::Model,
    summary: crate::analysis::summary::Summary,
    options: drawing::Options,
    /// `--envelope`'s chart, made already (it is small).
    chart: Option<String>,
}

impl Drawing {
    /// Write the SVG to `w`.
    pub fn write_to(&self, w: &mut dyn std::io::Write) -> std::io::Result<()> {
        if let Some(chart) = &self.chart {
            return w.write_all(chart.as_bytes());
        }
        drawing::write_svg(&self.model, &self.summary, &self.options, w)
    }
}

/// `--envelope`: the chart of the file's `[envelope]`, with the base's
/// point; an error without one.
fn envelope_chart(
    loaded: &crate::analysis::Loaded,
    settings: &Settings,
    title: &str,
) -> Result<String, Diagnostic> {
    let (Some(env), Some(base)) = (&loaded.model.envelope, &loaded.summary.envelope) else {
        return Err(Diagnostic::plain(
            "`--envelope` needs an `[envelope]` table in the part file, and it has none",
        )
        .help("give `[envelope]` with `axis` and `points` (docs/cases.md, \"The envelope\")"));
    };
    let (_, cases) =
        crate::analysis::cases::each(loaded.source.clone(), loaded.model.clone(), settings)?;
    let mut points = vec![("base".to_string(), *base)];
    points.extend((cases.iter()).filter_map(|(name, l)| Some((name.clone(), l.summary.envelope?))));
    let legs = crate::analysis::envelope::sequences::legs(loaded, settings)?;
    let chart = drawing::envelope::Chart {
        title,
        envelope: env,
        units: crate::output::format::DisplayUnits::of(loaded.model.units),
        points,
        paths: (legs.into_iter())
            .map(|l| (format!("{} → {}", l.from, l.to), l.curve))
            .collect(),
    };
    Ok(drawing::envelope::svg(&chart))
}
