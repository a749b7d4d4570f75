//! A robot description read with every file it includes followed
//! (issue 34): the link-by-link reader (`check`, `export`) and the whole
//! robot's (`Robot::read_in`) both start here, so that an included link is
//! named, placed and judged the same by each.

use super::sdf_include::{self, chain};
use super::{Resolve, Xml, mjcf, mjcf_include, parse, qname, root, sdf, sdf_tree, urdf};
use crate::diag::{Diagnostic, Source};
use crate::robot::{Description, Dialect};

/// `source` read as a robot description of `format`, every file it
/// includes followed (SDFormat `<include>`s of worlds and models, MJCF
/// `<include>`s), resolved by `r`: each link knows the file it is written
/// in (`Link::site`), and the description keeps those files
/// (`Description::files`). An SDFormat file's links are those of the whole
/// robot's reader (`sdf_tree`), named as it names them, when it includes
/// any file; else `sdf::read`'s, which reads every world and nested model.
pub fn read_in(source: &Source, format: Dialect, r: &Resolve) -> Result<Description, Diagnostic> {
    let doc = parse(source)?;
    let xml = Xml { source };
    let root = doc.root_element();
    self::root(&xml, root, format)?;
    match format {
        Dialect::Urdf => urdf::read(&xml, root),
        Dialect::Sdf => {
            let mut d = sdf::read(&xml, root)?;
            let files = sdf_include::load(source, r)?;
            if files.included.is_empty() {
                return Ok(d);
            }
            let tree = sdf_tree::of_files(&xml, &mut d, &files)?;
            sdf_tree::moving(&mut d, &tree);
            Ok(d)
        }
        Dialect::Mjcf => {
            if !root.descendants().any(|n| qname(n) == "include") {
                return mjcf::read(&xml, root);
            }
            let files = mjcf_include::load(source, r)?;
            let docs = mjcf_include::parse(&files)?;
            let m = mjcf_include::Model::of(&files, &docs);
            let mut d = mjcf::model(&m).map_err(|e| files.located(e))?;
            for l in &mut d.links {
                l.site.from = chain(&files.included, &files.from, l.site.file);
            }
            d.files = crate::robot::Included {
                sources: files.included.clone(),
                from: files.from.clone(),
            };
            Ok(d)
        }
    }
}

/// The directory of the robot file `source`, symlinks followed: the first
/// of the directories its includes may read (`sdf_include::roots`), and
/// the one `export --update` writes included files under.
pub fn canonical_dir(source: &Source) -> std::path::PathBuf {
    sdf_include::roots(source, &Resolve::default()).swap_remove(0)
}
