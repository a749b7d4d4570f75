//! The help texts of the command line: the exit statuses and each
//! command's examples, shown after its options.

pub(super) const EXIT_STATUS: &str = "\
Exit status:
  0  success
  1  `check`: an expectation or validity check failed; `diff`: something changed beyond --tol;
     `budget`: the predicted mass exceeds the limit
  2  an error: bad input, unreadable file, bad flag (nothing is printed on stdout)";

pub(super) const REPORT_HELP: &str = "\
Examples:
  massprop report arm.toml                        the short table, in the file's units
  massprop report arm.toml --full                 every table: radii, parts, sub-assemblies
  massprop report arm.toml --format json | jq .mass SI, each value with its error bound
  massprop report arm.toml --omega \"0,0,3000 rpm\" --about \"0,0,10 mm\"
  massprop report sat.toml --uncertainty linear   σ of each value from the file's tolerances
  massprop report sat.toml --uncertainty montecarlo --samples 20000 --seed 7";

pub(super) const BUDGET_HELP: &str = "\
Examples:
  massprop budget sat.toml                        groups, growth, predicted mass and margin
  massprop budget sat.toml --format json | jq .limit   SI
  massprop budget sat.toml --only payload         one sub-assembly (no limit: the limit is the whole body's)

Exit status 1 when `[budget] limit` (else `[expect] mass`'s `max`) is below the predicted mass.";

pub(super) const CHECK_HELP: &str = "\
Examples:
  massprop check .                      every part file here (ignored and hidden ones not)
  massprop check . --quiet              the failures and the summary line only
  massprop check . --format github      annotations on a GitHub pull request
  massprop check --bless arm.toml       write today's values into [expect]
  massprop check robot.urdf --engine mujoco   each link's inertial by MuJoCo's rule";

pub(super) const DIFF_HELP: &str = "\
Examples:
  massprop diff old.toml new.toml
  massprop diff old.toml new.toml --tol 1e-6 --format json
  massprop diff arm.toml robot.urdf --link forearm   a part file against a link's inertial";

pub(super) const EXPORT_HELP: &str = "\
Examples:
  massprop export arm.toml --to urdf                       the <inertial> element
  massprop export arm.toml --to mjcf --principal           diaginertia and quat
  massprop export arm.toml --update robot.urdf --link forearm --dry-run   the change, as a diff";

pub(super) const RENDER_HELP: &str = "\
Examples:
  massprop render arm.toml -o arm.svg             four views, legend, centre of mass, axes
  massprop render sat.toml --view iso > sat.svg   one view, larger
  massprop render sat.toml --only payload -o payload.svg   one sub-assembly
  massprop render plate.toml --omega \"0,0,30\" --about 0,0,0   with ω and the reference point

Views: front (x right, z up), top (x right, y up), side (y right, z up), iso (from (1, -1, 1)).
Colours by `group` if any part has one, else by `material`, else by shape (one kind a drawing);
cut-outs dashed, drawn over the parts; a legend names each colour and symbol.";

pub(super) const MATERIALS_HELP: &str = "\
Examples:
  massprop materials
  massprop materials arm.toml           with arm.toml's own [materials]";

pub(super) const COMPLETIONS_HELP: &str = "\
Examples:
  massprop completions bash > ~/.local/share/bash-completion/completions/massprop
  massprop completions zsh > ~/.zfunc/_massprop      # with fpath+=~/.zfunc
  massprop completions fish > ~/.config/fish/completions/massprop.fish";

pub(super) const MAN_HELP: &str = "\
Examples:
  massprop man > ~/.local/share/man/man1/massprop.1 && man massprop
  massprop man | man -l -";

pub(super) const SCHEMA_HELP: &str = "\
Examples:
  massprop schema > massprop.schema.json          then `#:schema ./massprop.schema.json` atop a part file
  massprop schema | jq '.\"$defs\".ShapeName.enum'  the shape names";

pub(super) const INIT_HELP: &str = "\
Examples:
  massprop init arm.toml                a new file (an existing one is left alone: exit 2)
  massprop init                         the starter on standard output
  massprop init arm.toml && massprop check arm.toml";
