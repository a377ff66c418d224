//! Step 5: Newton-Euler, the Motion Law and Kane's method -> a linear system in the q''
//! and the reactions.
