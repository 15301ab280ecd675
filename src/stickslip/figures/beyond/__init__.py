"""Figures beyond the paper: models the paper does not treat, each checked on closed forms."""
