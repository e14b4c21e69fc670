//! Regenerates the figures of the reference paper into `figures/`.
fn main() {
    eprintln!(
        "figures: not drawn yet; planned: fig3, fig4, fig5, fig6, fig7, regime_map, field_snapshot"
    );
}
