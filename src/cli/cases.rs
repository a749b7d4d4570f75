//! `report`'s flags of loading cases (`[[case]]`, docs/cases.md):
//! `--case NAME` and `--cases`.

use clap::Args;

#[derive(Args, Debug, Default)]
pub struct CaseArgs {
    /// Report the file's `[[case]]` NAME, exactly as a plain report of
    /// the file edited to that case (its `params`, without its `without`
    /// parts and `without_groups`).
    #[arg(long, value_name = "NAME", conflicts_with = "cases")]
    pub case: Option<String>,

    /// One row per `[[case]]` (the base first): mass, centre of mass,
    /// principal moments and axle loads (`--full` adds the inertia); JSON:
    /// the base's report with `cases`, each case's whole report.
    #[arg(long)]
    pub cases: bool,
}

impl CaseArgs {
    /// The report's options of cases.
    pub fn selection(&self) -> crate::commands::report::Cases {
        match (&self.case, self.cases) {
            (Some(name), _) => crate::commands::report::Cases::One(name.clone()),
            (None, true) => crate::commands::report::Cases::All,
            (None, false) => crate::commands::report::Cases::Base,
        }
    }
}
