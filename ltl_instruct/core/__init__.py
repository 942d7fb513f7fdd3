"""Core library of ltl_instruct: pure Python, never imports rclpy."""
