//! Ordering a compiled program for the processor. Instructions are grouped by level (an
//! instruction's level is one more than its operands' highest), and within a level like
//! instructions go together. Any order within a level is valid, and long runs of one kind
//! let the processor predict what comes next: deciding what each instruction is, not the
//! arithmetic, is most of the cost of running the program.

use super::instr::Instr;

/// The instructions reordered, with every slot renumbered, and the outputs renumbered.
///
/// Slots below `inputs` are the inputs; slot `inputs + i` is instruction `i`'s result.
pub(super) fn schedule(
    inputs: usize,
    instructions: &[Instr],
    outputs: &[usize],
) -> (Vec<Instr>, Vec<usize>) {
    let mut level = vec![0u32; instructions.len()];
    for (i, instr) in instructions.iter().enumerate() {
        // Operands come before their users, so their levels are known.
        level[i] = instr
            .operands()
            .into_iter()
            .filter_map(|slot| (slot as usize).checked_sub(inputs))
            .map(|operand| level[operand] + 1)
            .max()
            .unwrap_or(0);
    }
    let mut order: Vec<usize> = (0..instructions.len()).collect();
    order.sort_by_key(|&i| (level[i], instructions[i].kind(), i));
    let mut new_slot = vec![0u32; instructions.len()];
    for (position, &old) in order.iter().enumerate() {
        new_slot[old] = (inputs + position) as u32;
    }
    let renumber = |slot: u32| match (slot as usize).checked_sub(inputs) {
        Some(old) => new_slot[old],
        None => slot,
    };
    let reordered = order
        .iter()
        .map(|&old| instructions[old].renumbered(renumber))
        .collect();
    let outputs = outputs
        .iter()
        .map(|&s| renumber(s as u32) as usize)
        .collect();
    (reordered, outputs)
}
