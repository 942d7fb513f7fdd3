"""Thin rclpy nodes: parameters in, core call, messages out."""
