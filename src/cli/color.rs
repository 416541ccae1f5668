//! Whether the human report is coloured: `--color always|never`, or for `auto` (the
//! default) what the environment says, in the order anstream (clap, cargo) applies the
//! conventions, with FORCE_COLOR beside CLICOLOR_FORCE:
//!
//! 1. `NO_COLOR` non-empty: no colour (<https://no-color.org>);
//! 2. `CLICOLOR_FORCE` other than `0`, or `FORCE_COLOR` non-empty and other than `0` or
//!    `false`: colour, even into a pipe or file (<https://bixense.com/clicolors/>,
//!    <https://force-color.org>);
//! 3. `CLICOLOR=0`: no colour;
//! 4. otherwise colour when the report goes to a terminal whose `TERM` is set and not
//!    `dumb`, or `CLICOLOR` is set (not `0`), or a CI service is detected.
//!
//! anstyle-query reads NO_COLOR, CLICOLOR, TERM and the CI variables. CLICOLOR_FORCE is
//! read here because anstyle-query takes `CLICOLOR_FORCE=0` as forcing, which the
//! convention's text does not.

use clap::ValueEnum;

#[derive(Copy, Clone, Debug, Default, PartialEq, Eq, ValueEnum)]
pub enum ColorChoice {
    /// Colour on a terminal, as the environment says
    #[default]
    Auto,
    Always,
    Never,
}

/// What the environment says about colour, read once.
#[derive(Clone, Debug, Default)]
pub struct ColorEnv {
    no_color: bool,
    force: bool,
    clicolor: Option<bool>,
    term_supports_color: bool,
    is_ci: bool,
}

impl ColorEnv {
    pub fn from_process() -> ColorEnv {
        let var = |name: &str| std::env::var_os(name);
        let clicolor_force = var("CLICOLOR_FORCE").is_some_and(|v| !v.is_empty() && v != "0");
        let force_color =
            var("FORCE_COLOR").is_some_and(|v| !v.is_empty() && v != "0" && v != "false");
        ColorEnv {
            no_color: anstyle_query::no_color(),
            force: clicolor_force || force_color,
            clicolor: anstyle_query::clicolor(),
            term_supports_color: anstyle_query::term_supports_color(),
            is_ci: anstyle_query::is_ci(),
        }
    }
}

/// Whether to colour a report going to a terminal (`terminal`) or not.
pub fn use_color(choice: ColorChoice, env: &ColorEnv, terminal: bool) -> bool {
    match choice {
        ColorChoice::Always => true,
        ColorChoice::Never => false,
        ColorChoice::Auto if env.no_color => false,
        ColorChoice::Auto if env.force => true,
        ColorChoice::Auto if env.clicolor == Some(false) => false,
        ColorChoice::Auto => {
            terminal && (env.term_supports_color || env.clicolor == Some(true) || env.is_ci)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A terminal with TERM=xterm and nothing else set.
    fn xterm() -> ColorEnv {
        ColorEnv {
            term_supports_color: true,
            ..ColorEnv::default()
        }
    }

    #[test]
    fn the_conventions_apply_in_order() {
        let auto = |env: &ColorEnv, terminal| use_color(ColorChoice::Auto, env, terminal);
        assert!(auto(&xterm(), true));
        assert!(!auto(&xterm(), false), "a pipe");
        assert!(!auto(&ColorEnv::default(), true), "TERM=dumb or unset");
        let no_color = ColorEnv {
            no_color: true,
            force: true,
            ..xterm()
        };
        assert!(!auto(&no_color, true), "NO_COLOR wins over forcing");
        let force = ColorEnv {
            force: true,
            clicolor: Some(false),
            ..ColorEnv::default()
        };
        assert!(auto(&force, false), "forced into a pipe, over CLICOLOR=0");
        let clicolor_0 = ColorEnv {
            clicolor: Some(false),
            ..xterm()
        };
        assert!(!auto(&clicolor_0, true));
        let clicolor_1 = ColorEnv {
            clicolor: Some(true),
            ..ColorEnv::default()
        };
        assert!(auto(&clicolor_1, true), "CLICOLOR=1 on a dumb terminal");
        assert!(
            !auto(&clicolor_1, false),
            "CLICOLOR=1 does not colour a pipe"
        );
        let ci = ColorEnv {
            is_ci: true,
            ..ColorEnv::default()
        };
        assert!(auto(&ci, true) && !auto(&ci, false));
    }

    #[test]
    fn the_flag_wins_over_the_environment() {
        let no_color = ColorEnv {
            no_color: true,
            ..xterm()
        };
        assert!(use_color(ColorChoice::Always, &no_color, false));
        let force = ColorEnv {
            force: true,
            ..xterm()
        };
        assert!(!use_color(ColorChoice::Never, &force, true));
    }
}
